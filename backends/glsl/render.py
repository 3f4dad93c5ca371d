"""Rendering plans into GLSL text with jinja2 (templates/*.j2, snippets/*.glsl): a ShaderWriter
loads the templates, snippets and tables once and keeps them for its lifetime (the target's)."""

from __future__ import annotations

import re
from functools import cached_property
from importlib import resources
from typing import Any

import jinja2

from cnlmc.bsdf.multiscatter import TABLE_SIZE, albedo_table, average_albedo_table

#: profile -> how its sources start and whether uniforms may carry initialisers.
PROFILES = {
    "330": {"version": "#version 330 core", "precision": (), "initializers": True, "glsl_stage_flag": "330"},
    "es300": {
        "version": "#version 300 es",
        "precision": ("precision highp float;", "precision highp int;"),
        "initializers": False,
        "glsl_stage_flag": "es300",
    },
}

_UNSAFE_IN_COMMENT = re.compile(r"[^\x20-\x7e]")


def comment_text(text: object) -> str:
    """Make any text safe inside a // or /* */ comment: one line, printable ASCII,
    no comment delimiters, no line-continuation backslash. The one place phrases
    (user text) enter GLSL."""
    flat = " ".join(str(text).split())  # newlines, tabs, form feeds -> single spaces
    flat = _UNSAFE_IN_COMMENT.sub(lambda m: f"<U+{ord(m.group()):04X}>", flat)
    return flat.replace("\\", "<backslash>").replace("*/", "* /").replace("/*", "/ *")


def _float(x: float) -> str:
    text = repr(float(x))
    if "inf" in text or "nan" in text:
        raise ValueError(f"glsl: non-finite value {text} cannot be a uniform")
    return text if ("." in text or "e" in text) else text + ".0"


def glsl_value(value: Any, gl_type: str) -> str:
    """A Python float / list as a GLSL literal of `gl_type`."""
    if gl_type == "float":
        return _float(value)
    if gl_type == "int":
        return str(int(value))
    return f"{gl_type}({', '.join(_float(v) for v in value)})"


def _literal(value: float) -> str:
    """A table entry as a 9-digit GLSL float literal."""
    text = format(float(value), ".9g")
    return text if any(c in text for c in ".e") else text + ".0"


class ShaderWriter:
    """The jinja2 environment, the snippet files and the multiscatter tables, each loaded on
    first use and kept while this writer lives."""

    def __init__(self) -> None:
        self._snippets: dict[str, str] = {}

    @cached_property
    def environment(self) -> jinja2.Environment:
        env = jinja2.Environment(
            loader=jinja2.PackageLoader("cnlmc.backends.glsl", "templates"),
            undefined=jinja2.StrictUndefined,
            keep_trailing_newline=True,
            trim_blocks=True,
            lstrip_blocks=True,
            autoescape=False,
        )
        env.filters["comment"] = comment_text
        env.filters["glsl_value"] = glsl_value
        return env

    def snippet(self, name: str) -> str:
        if name not in self._snippets:
            folder = resources.files("cnlmc.backends.glsl").joinpath("snippets")
            self._snippets[name] = folder.joinpath(f"{name}.glsl").read_text("utf-8")
        return self._snippets[name]

    @cached_property
    def multiscatter_tables(self) -> dict[str, Any]:
        """The reference tables as missing energy 1 - E(mu, alpha) and 1 - E_avg(alpha), 9-digit literals."""
        rows = [[_literal(v) for v in row] for row in 1.0 - albedo_table()]
        return {"size": TABLE_SIZE, "table": rows, "average": [_literal(v) for v in 1.0 - average_albedo_table()]}

    def render(self, template: str, **context: Any) -> str:
        return self.environment.get_template(template).render(**context)
