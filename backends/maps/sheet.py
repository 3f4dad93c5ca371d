"""Contact sheet: every stdlib graph's outputs, one row per graph, labelled (matplotlib)."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from cnlmc.output import write_files

from .colour import linear_to_srgb
from .evaluate import evaluate
from .library import graph_names, load_graph
from .roles import COLOR_ROLES


def display_pixels(role: str, array: np.ndarray) -> np.ndarray:
    """sRGB-ish RGB in [0, 1] for showing a map of any role."""
    if role in COLOR_ROLES:
        return linear_to_srgb(array)
    if role == "normal":
        return np.clip(array * 0.5 + 0.5, 0.0, 1.0)
    return np.repeat(np.clip(array, 0.0, 1.0)[..., None], 3, axis=-1)


def sheet_rows(size: int, seed: int = 0) -> list[tuple[str, dict[str, np.ndarray]]]:
    return [(name, evaluate(load_graph(name), size, seed)) for name in graph_names()]


def size_note(name: str) -> str:
    """The graph's real size for the first tile's title: the tile's width and its feature size."""
    scale = load_graph(name).scale
    if scale is None:
        return ""
    return f"\n{scale.metres_per_unit * 1000:.0f} mm tile, {scale.feature * 1000:g} mm"


def render_contact_sheet(path, size: int = 256, seed: int = 0) -> Path:
    """Write a PNG with one row per stdlib graph and one labelled tile per output."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = sheet_rows(size, seed)
    columns = max(len(outputs) for _, outputs in rows)
    figure, axes = plt.subplots(len(rows), columns, figsize=(2.1 * columns, 2.25 * len(rows)), squeeze=False)
    for axis_row, (name, outputs) in zip(axes, rows):
        tiles = list(outputs.items())
        for column, axis in enumerate(axis_row):
            axis.set_axis_off()
            if column < len(tiles):
                role, array = tiles[column]
                axis.imshow(display_pixels(role, array), interpolation="nearest")
                axis.set_title(f"{name}: {role}{size_note(name) if column == 0 else ''}", fontsize=9)
    figure.tight_layout()
    return save_atomically(figure, Path(path))


def save_atomically(figure, path: Path) -> Path:
    """The figure as a PNG, written through the one output writer (cnlmc.output: atomic, only a
    regular file, a usage error naming the path when it cannot be written)."""
    import matplotlib.pyplot as plt

    png = io.BytesIO()
    figure.savefig(png, format="png", dpi=100)
    plt.close(figure)
    [written] = write_files([(path, png.getvalue())])
    return written
