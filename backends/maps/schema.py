"""Schema check of graph TOML files; every error names the file and the dotted key."""

from __future__ import annotations

import re
from numbers import Real

from .errors import GraphSchemaError, did_you_mean
from .registry import NODE_TYPES, REQUIRED, Input
from .spec import OUTPUT_ROLES, Graph, GraphInput, GraphParam, GraphScale, NodeSpec, Ref

TOP_KEYS = ("name", "doc", "params", "inputs", "nodes", "outputs", "presets", "scale", "palette")
SCALE_KEYS = ("metres_per_unit", "feature", "what", "measure", "axis", "source")
SCALE_AXES = ("u", "v", "any")
PALETTE_KEYS = (
    "max_chroma",
    "hue_range",
    "hue_reach",
    "off_hue_max_chroma",
    "lightness",
    "lightness_curve",
    "dark_below",
    "dark_params",
    "shade",
    "source",
)
REF_KEYS = ("node", "param", "input", "mul", "add")
IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]{0,63}")  # names that end up in node names and file names


class Checker:
    """Carries the file name so that every complaint says where it comes from."""

    def __init__(self, file: str):
        self.file = file

    def fail(self, key: str, message: str):
        raise GraphSchemaError(f"{self.file}: {key}: {message}")

    def known_keys(self, table: dict, allowed, where: str):
        for key in table:
            if key not in allowed:
                self.fail(f"{where}.{key}".lstrip("."), f"unknown key '{key}'{did_you_mean(key, allowed)}")

    def names(self, table: dict, key: str) -> dict:
        """A table whose keys are names (nodes, params, inputs, presets): each a plain identifier."""
        for name in table:
            if not IDENTIFIER.fullmatch(name):
                self.fail(f"{key}.{name}", f"'{name}' is not a plain name (letters, digits and '_', at most 64)")
        return table

    def table(self, value, key: str) -> dict:
        if not isinstance(value, dict):
            self.fail(key, f"expected a table, got {type(value).__name__}")
        return value

    def string(self, value, key: str) -> str:
        if not isinstance(value, str):
            self.fail(key, "expected a string")
        return value

    def number(self, value, key: str) -> float:
        if isinstance(value, bool) or not isinstance(value, Real):
            self.fail(key, f"expected a number, got {value!r}")
        return float(value)

    def rgb(self, value, key: str) -> tuple[float, float, float]:
        if not isinstance(value, list) or len(value) != 3:
            self.fail(key, f"expected an RGB triple [r, g, b], got {value!r}")
        r, g, b = (self.number(c, f"{key}[{i}]") for i, c in enumerate(value))
        return r, g, b


def check_param(c: Checker, name: str, raw) -> GraphParam:
    key = f"params.{name}"
    table = c.table(raw, key)
    c.known_keys(table, ("default", "range", "doc"), key)
    for required in ("default", "range", "doc"):
        if required not in table:
            c.fail(f"{key}.{required}", "missing")
    default = c.number(table["default"], f"{key}.default")
    bounds = table["range"]
    if not isinstance(bounds, list) or len(bounds) != 2:
        c.fail(f"{key}.range", "expected [min, max]")
    low, high = (c.number(b, f"{key}.range") for b in bounds)
    if not low <= default <= high:
        c.fail(f"{key}.default", f"{default} is outside the range [{low}, {high}]")
    return GraphParam(default, low, high, c.string(table["doc"], f"{key}.doc"))


def check_input(c: Checker, name: str, raw) -> GraphInput:
    key = f"inputs.{name}"
    table = c.table(raw, key)
    c.known_keys(table, ("default", "doc"), key)
    default = table.get("default")
    value = c.rgb(default, f"{key}.default") if isinstance(default, list) else c.number(default, f"{key}.default")
    return GraphInput(value, c.string(table.get("doc"), f"{key}.doc"))


def check_ref(c: Checker, graph_names: dict, raw: dict, key: str) -> Ref:
    c.known_keys(raw, REF_KEYS, key)
    sources = [s for s in ("node", "param", "input") if s in raw]
    if len(sources) != 1:
        c.fail(key, "a reference needs exactly one of node=, param=, input=")
    source = sources[0]
    name = c.string(raw[source], f"{key}.{source}")
    if name not in graph_names[source]:
        c.fail(f"{key}.{source}", f"unknown {source} '{name}'{did_you_mean(name, graph_names[source])}")
    if source == "node" and ("mul" in raw or "add" in raw):
        c.fail(key, "mul/add apply to param= and input= references only")
    mul, add = (c.number(raw.get(k, d), f"{key}.{k}") for k, d in (("mul", 1.0), ("add", 0.0)))
    return Ref(source, name, mul, add)


def check_value(c: Checker, names: dict, spec: Input, raw, key: str):
    """Check one node input against its declared kind; return the parsed value."""
    if isinstance(raw, dict):
        if spec.kind in ("enum", "bool", "colors", "floats"):
            c.fail(key, f"a {spec.kind} input cannot be a reference")
        ref = check_ref(c, names, raw, key)
        if ref.source == "node" and spec.kind != "map":
            c.fail(key, f"a {spec.kind} input takes a constant or a param=/input= reference, not a node")
        return ref
    return check_constant(c, names, spec, raw, key)


def check_constant(c: Checker, names: dict, spec: Input, raw, key: str):
    kind = spec.kind
    if kind == "enum":
        if raw not in spec.choices:
            c.fail(key, f"'{raw}' is not one of {', '.join(spec.choices)}{did_you_mean(str(raw), spec.choices)}")
        return raw
    if kind == "bool":
        if not isinstance(raw, bool):
            c.fail(key, "expected true or false")
        return raw
    if kind == "colors":
        if not isinstance(raw, list) or len(raw) < 2:
            c.fail(key, "expected a list of at least two colours")
        return [check_value(c, names, Input("color"), item, f"{key}[{i}]") for i, item in enumerate(raw)]
    if kind == "floats":
        if not isinstance(raw, list):
            c.fail(key, "expected a list of numbers")
        return [c.number(x, f"{key}[{i}]") for i, x in enumerate(raw)]
    if kind == "color" or (kind == "map" and isinstance(raw, list)):
        return c.rgb(raw, key)
    value = c.number(raw, key)
    return int(round(value)) if kind == "int" else value


def check_node(c: Checker, names: dict, name: str, raw) -> NodeSpec:
    key = f"nodes.{name}"
    table = c.table(raw, key)
    if "type" not in table:
        c.fail(f"{key}.type", "missing")
    node_type = c.string(table["type"], f"{key}.type")
    if node_type not in NODE_TYPES:
        c.fail(f"{key}.type", f"unknown node type '{node_type}'{did_you_mean(node_type, NODE_TYPES)}")
    inputs = NODE_TYPES[node_type].inputs
    args = {}
    for arg, value in table.items():
        if arg == "type":
            continue
        if arg not in inputs:
            c.fail(f"{key}.{arg}", f"unknown input '{arg}' for node type '{node_type}'{did_you_mean(arg, inputs)}")
        args[arg] = check_value(c, names, inputs[arg], value, f"{key}.{arg}")
    for arg, spec in inputs.items():
        if spec.default is REQUIRED and arg not in args:
            c.fail(f"{key}.{arg}", f"required input of '{node_type}' is missing")
    return NodeSpec(node_type, args)


def node_refs(value):
    if isinstance(value, Ref):
        return [value.name] if value.source == "node" else []
    if isinstance(value, list):
        return [name for item in value for name in node_refs(item)]
    return []


def check_acyclic(c: Checker, nodes: dict[str, NodeSpec]):
    state: dict[str, str] = {}

    def visit(name, path):
        if state.get(name) == "done":
            return
        if state.get(name) == "active":
            c.fail(f"nodes.{name}", "cycle: " + " -> ".join(path + [name]))
        state[name] = "active"
        for arg in nodes[name].args.values():
            for dep in node_refs(arg):
                visit(dep, path + [name])
        state[name] = "done"

    for name in nodes:
        visit(name, [])


def check_outputs(c: Checker, raw, nodes) -> dict[str, str]:
    table = c.table(raw, "outputs")
    c.known_keys(table, OUTPUT_ROLES, "outputs")
    for role, node in table.items():
        if c.string(node, f"outputs.{role}") not in nodes:
            c.fail(f"outputs.{role}", f"unknown node '{node}'{did_you_mean(node, nodes)}")
    if not table:
        c.fail("outputs", "a graph needs at least one output")
    return dict(table)


def check_presets(c: Checker, raw, params: dict[str, GraphParam]) -> dict:
    presets = {}
    for preset, values in c.names(c.table(raw, "presets"), "presets").items():
        key = f"presets.{preset}"
        c.known_keys(c.table(values, key), params, key)
        presets[preset] = {p: c.number(v, f"{key}.{p}") for p, v in values.items()}
        for p, v in presets[preset].items():
            if not params[p].low <= v <= params[p].high:
                c.fail(f"{key}.{p}", f"{v} is outside the range [{params[p].low}, {params[p].high}]")
    return presets


def check_scale(c: Checker, raw, outputs: dict[str, str]) -> GraphScale:
    """The `[scale]` table: every key present, sizes positive metres, `measure` one of the outputs."""
    table = c.table(raw, "scale")
    c.known_keys(table, SCALE_KEYS, "scale")
    for required in SCALE_KEYS:
        if required not in table:
            c.fail(f"scale.{required}", "missing")
    unit, feature = (c.number(table[k], f"scale.{k}") for k in ("metres_per_unit", "feature"))
    for key, value in (("metres_per_unit", unit), ("feature", feature)):
        if not value > 0:
            c.fail(f"scale.{key}", f"expected a size in metres above 0, got {value}")
    measure = c.string(table["measure"], "scale.measure")
    if measure not in outputs:
        c.fail("scale.measure", f"'{measure}' is not an output{did_you_mean(measure, outputs)}")
    axis = c.string(table["axis"], "scale.axis")
    if axis not in SCALE_AXES:
        c.fail("scale.axis", f"expected one of {', '.join(SCALE_AXES)}, got '{axis}'")
    what, source = (c.string(table[k], f"scale.{k}") for k in ("what", "source"))
    return GraphScale(unit, feature, what, measure, axis, source)


def _check_hue_range(c: Checker, table: dict) -> None:
    """`hue_range` [start, end] OKLCh degrees (counter-clockwise from start), `hue_reach` degrees
    beyond it, `off_hue_max_chroma` an OKLab chroma: the three together or none."""
    given = [k for k in ("hue_range", "hue_reach", "off_hue_max_chroma") if k in table]
    if given and len(given) != 3:
        c.fail("palette.hue_range", "expected hue_range, hue_reach and off_hue_max_chroma together")
    if not given:
        return
    bounds = table["hue_range"]
    if not isinstance(bounds, list) or len(bounds) != 2:
        c.fail("palette.hue_range", "expected [start, end] OKLCh hue in degrees")
    if not all(0 <= c.number(h, "palette.hue_range") < 360 for h in bounds):
        c.fail("palette.hue_range", "expected hues in [0, 360)")
    if not 0 <= c.number(table["hue_reach"], "palette.hue_reach") <= 180:
        c.fail("palette.hue_reach", "expected degrees in [0, 180]")
    if not 0 <= c.number(table["off_hue_max_chroma"], "palette.off_hue_max_chroma") <= 0.4:
        c.fail("palette.off_hue_max_chroma", "expected an OKLab chroma in [0, 0.4]")


def check_palette(c: Checker, raw, params: dict[str, GraphParam]) -> dict:
    """The `[palette]` table (what a colour word does to the graph's colours; read by the compiler's
    compiler/passes/textured_colour.py): OKLab chroma cap and lightness range, the graph
    parameters a dark named colour sets (light veins in a black marble), and the parameters a
    'darker' / 'lighter' step moves (`shade`: the graph's own colours, toward black or a light end)."""
    table = c.table(raw, "palette")
    c.known_keys(table, PALETTE_KEYS, "palette")
    if "max_chroma" in table and not 0 <= c.number(table["max_chroma"], "palette.max_chroma") <= 0.4:
        c.fail("palette.max_chroma", "expected an OKLab chroma in [0, 0.4]")
    _check_hue_range(c, table)
    if "lightness" in table:
        bounds = table["lightness"]
        if not isinstance(bounds, list) or len(bounds) != 2:
            c.fail("palette.lightness", "expected [min, max] OKLab lightness")
        low, high = (c.number(b, "palette.lightness") for b in bounds)
        if not 0 <= low <= high <= 1:
            c.fail("palette.lightness", f"expected 0 <= min <= max <= 1, got [{low}, {high}]")
    if "lightness_curve" in table and not 0.25 <= c.number(table["lightness_curve"], "palette.lightness_curve") <= 4:
        c.fail("palette.lightness_curve", "expected an exponent in [0.25, 4]")
    if "dark_below" in table:
        c.number(table["dark_below"], "palette.dark_below")
    settings = c.table(table.get("dark_params", {}), "palette.dark_params")
    c.known_keys(settings, params, "palette.dark_params")
    for name, value in settings.items():
        v = c.number(value, f"palette.dark_params.{name}")
        if not params[name].low <= v <= params[name].high:
            c.fail(f"palette.dark_params.{name}", f"{v} is outside the range [{params[name].low}, {params[name].high}]")
    shade = c.table(table.get("shade", {}), "palette.shade")
    c.known_keys(shade, ("darken", "lighten"), "palette.shade")
    for way, name in shade.items():
        if c.string(name, f"palette.shade.{way}") not in params:
            c.fail(f"palette.shade.{way}", f"'{name}' is not a parameter of this graph")
    c.string(table.get("source", ""), "palette.source")
    return dict(table)


def check_graph(raw: dict, file: str, stem: str) -> Graph:
    c = Checker(file)
    c.known_keys(raw, TOP_KEYS, "")
    for required in ("doc", "nodes", "outputs"):
        if required not in raw:
            c.fail(required, "missing")
    name = c.string(raw.get("name", stem), "name")
    if not IDENTIFIER.fullmatch(name):
        c.fail("name", f"'{name}' is not a plain name (letters, digits and '_', at most 64)")
    if name != stem:
        c.fail("name", f"'{name}' differs from the file name '{stem}'")
    params = {k: check_param(c, k, v) for k, v in c.names(c.table(raw.get("params", {}), "params"), "params").items()}
    inputs = {k: check_input(c, k, v) for k, v in c.names(c.table(raw.get("inputs", {}), "inputs"), "inputs").items()}
    raw_nodes = c.names(c.table(raw["nodes"], "nodes"), "nodes")
    names = {"node": raw_nodes, "param": params, "input": inputs}
    nodes = {k: check_node(c, names, k, v) for k, v in raw_nodes.items()}
    check_acyclic(c, nodes)
    outputs = check_outputs(c, raw["outputs"], nodes)
    presets = check_presets(c, raw.get("presets", {}), params)
    scale = check_scale(c, raw["scale"], outputs) if "scale" in raw else None
    check_palette(c, raw.get("palette", {}), params)
    graph = Graph(name, c.string(raw["doc"], "doc"), file, params, inputs, nodes, outputs, presets, scale)
    return graph
