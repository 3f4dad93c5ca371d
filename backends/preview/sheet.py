"""Images out: PNG encoding, labelled tiles and the side-by-side sheet of 'or' variants."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from cnlmc.material import Material


def png_bytes(rgba: np.ndarray) -> bytes:
    import cv2

    image = cv2.cvtColor(rgba, cv2.COLOR_RGBA2BGRA if rgba.shape[2] == 4 else cv2.COLOR_RGB2BGR)
    ok, data = cv2.imencode(".png", image)
    if not ok:
        raise RuntimeError("preview: PNG encoding failed")
    return data.tobytes()


def over(rgba: np.ndarray, background=(0.5, 0.5, 0.5)) -> np.ndarray:
    """Composite premultiplied-free RGBA (uint8) over a constant colour -> opaque RGBA."""
    a = rgba[..., 3:4].astype(np.float32) / 255.0
    rgb = rgba[..., :3].astype(np.float32) * a + np.asarray(background, np.float32) * 255.0 * (1 - a)
    return np.dstack([np.round(rgb).astype(np.uint8), np.full(rgba.shape[:2], 255, np.uint8)])


def label(tile: np.ndarray, text: str) -> np.ndarray:
    """The tile with a caption strip at the bottom (ASCII only, shortened to fit)."""
    import cv2

    h, w = tile.shape[:2]
    strip = max(14, h // 12)
    out = np.vstack([tile, np.full((strip, w, 4), (32, 32, 32, 255), np.uint8)])
    scale = strip / 30.0
    text = text.encode("ascii", "replace").decode()
    while text and cv2.getTextSize(text, cv2.FONT_HERSHEY_SIMPLEX, scale, 1)[0][0] > w - 6:
        text = text[:-2] + "~" if len(text) > 2 else ""
    cv2.putText(
        out, text, (3, h + int(strip * 0.72)), cv2.FONT_HERSHEY_SIMPLEX, scale, (235, 235, 235, 255), 1, cv2.LINE_AA
    )
    return out


def groups_of(materials: Sequence[Material]) -> list[list[Material]]:
    """Materials grouped by variant.group (in order of first appearance); others alone."""
    groups: dict[str, list[Material]] = {}
    for index, m in enumerate(materials):
        key = (m.variant.group if m.variant else "") or f"\0{index}"
        groups.setdefault(key, []).append(m)
    return list(groups.values())


def sheet(rows: list[list[np.ndarray]], gap: int = 4) -> np.ndarray:
    """Tiles (all the same size) in rows; short rows are padded with background."""
    h, w = rows[0][0].shape[:2]
    cols = max(len(r) for r in rows)
    out = np.full((len(rows) * (h + gap) - gap, cols * (w + gap) - gap, 4), (20, 20, 20, 255), np.uint8)
    for i, row in enumerate(rows):
        for j, tile in enumerate(row):
            out[i * (h + gap) : i * (h + gap) + h, j * (w + gap) : j * (w + gap) + w] = tile
    return out
