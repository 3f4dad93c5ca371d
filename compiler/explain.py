"""`cnlmc explain`: every parameter of every material with the words and rules that set it.
Text from the source or a lexicon (names, phrases, words, rules) is printed with its control
characters escaped (cnlmc.diagnostics.visible)."""

from __future__ import annotations

from typing import Any

from .diagnostics import visible


def _fmt(value: Any) -> str:
    if isinstance(value, list):
        return "(" + ", ".join(f"{v:.4g}" if isinstance(v, float) else str(v) for v in value) + ")"
    if isinstance(value, float):
        return f"{value:.4g}"
    return str(value)


def explain_material(material: dict[str, Any]) -> list[str]:
    model = material["model"]
    parts = [model["base"]] + [k for k in ("anisotropic", "coat") if model[k]]
    lines = [
        visible(f"{material['name']}: {material['phrase']}", one_line=True),
        f"  model: {' + '.join(parts)}"
        + (f", {model['distribution']}" if model["distribution"] else "")
        + (f", {model['diffuse']} diffuse" if model["diffuse"] else ""),
    ]
    rows = [("parameter", "value", "set by", "rule")]
    for param, steps in material["provenance"].items():
        for i, step in enumerate(steps):
            words, rule = visible(" ".join(step["words"]), one_line=True), visible(step["rule"], one_line=True)
            rows.append((param if i == 0 else "", visible(_fmt(step["value"]), one_line=True), words, rule))
    lines += _table(rows)
    return lines


def _table(rows: list[tuple[str, str, str, str]]) -> list[str]:
    widths = [min(max(len(r[i]) for r in rows), 40) for i in range(3)]
    out = []
    for n, row in enumerate(rows):
        cells = [row[i][:40].ljust(widths[i]) for i in range(3)]
        out.append("  " + "  ".join(cells) + "  " + row[3])
        if n == 0:
            out.append("  " + "  ".join("-" * w for w in widths) + "  " + "-" * 4)
    return out


def explain(ir: dict[str, Any]) -> str:
    blocks = ["\n".join(explain_material(m)) for m in ir["materials"]]
    return "\n\n".join(blocks) + "\n"
