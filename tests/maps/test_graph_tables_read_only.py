"""The compiler's view of the bundled graphs is shared by every caller in a process: nothing a
caller gets back can change what the next caller reads (compiler/graphs.py)."""

from __future__ import annotations

import pytest

from cnlmc.graphs import graph_names, graph_palette, graph_params


def test_a_palette_cannot_be_changed_by_a_caller():
    palette = graph_palette("brick")
    assert palette["lightness"] == (0.3, 0.8)
    with pytest.raises(TypeError):
        palette["max_chroma"] = 9.0  # type: ignore[index]
    with pytest.raises(AttributeError):
        palette["lightness"].append(1.0)  # a tuple, not the list the next caller would read
    assert graph_palette("brick")["max_chroma"] == pytest.approx(0.099)


def test_every_graph_reads_back_read_only_at_every_depth():
    for name in graph_names():
        for low, high, default in graph_params(name).values():
            assert low <= high and isinstance(default, float)
        stack: list[object] = [graph_palette(name)]
        while stack:
            value = stack.pop()
            assert not isinstance(value, (dict, list)), (name, value)
            if hasattr(value, "values"):
                stack.extend(value.values())  # type: ignore[union-attr]
            elif isinstance(value, tuple):
                stack.extend(value)
