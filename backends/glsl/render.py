"""Rendering plans into GLSL text with jinja2 (templates/*.j2, snippets/*.glsl)."""

from __future__ import annotations

import re
from functools import cache, lru_cache
from importlib import resources

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


def comment_text(text) -> str:
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


def glsl_value(value, gl_type: str) -> str:
    """A Python float / list as a GLSL literal of `gl_type`."""
    if gl_type == "float":
        return _float(value)
    if gl_type == "int":
        return str(int(value))
    return f"{gl_type}({', '.join(_float(v) for v in value)})"


@lru_cache(maxsize=1)
def environment() -> jinja2.Environment:
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


@cache
def snippet(name: str) -> str:
    return resources.files("cnlmc.backends.glsl").joinpath("snippets", f"{name}.glsl").read_text("utf-8")


@lru_cache(maxsize=1)
def multiscatter_tables() -> dict:
    """The reference tables as missing energy 1 − E(μ, α) and 1 − E_avg(α), 9-digit literals."""
    fmt = lambda v: format(float(v), ".9g")
    fix = lambda s: s if any(c in s for c in ".e") else s + ".0"
    rows = [[fix(fmt(v)) for v in row] for row in 1.0 - albedo_table()]
    return {"size": TABLE_SIZE, "table": rows, "average": [fix(fmt(v)) for v in 1.0 - average_albedo_table()]}


def render(template: str, **context) -> str:
    return environment().get_template(template).render(**context)
