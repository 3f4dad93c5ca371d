"""Graph files are checked at load: errors name the file and the key."""

import pytest

from cnlmc.backends.maps import GraphSchemaError, MapError, bake, load_graph, load_graph_file

GOOD = """
doc = "test"
[params.scale]
default = 1.0
range = [0.5, 2.0]
doc = "density"
[nodes.noise]
type = "perlin"
scale = { param = "scale", mul = 4 }
[outputs]
mask = "noise"
"""


def write(tmp_path, text, name="g"):
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    return path


def error_for(tmp_path, text):
    with pytest.raises(GraphSchemaError) as caught:
        load_graph_file(write(tmp_path, text))
    return str(caught.value)


def test_good_graph_loads(tmp_path):
    graph = load_graph_file(write(tmp_path, GOOD))
    assert graph.outputs == {"mask": "noise"}


def test_unknown_node_type_suggests(tmp_path):
    message = error_for(tmp_path, GOOD.replace('type = "perlin"', 'type = "perlinn"'))
    assert "g.toml" in message and "nodes.noise.type" in message
    assert "did you mean 'perlin'" in message


def test_unknown_input_suggests(tmp_path):
    message = error_for(tmp_path, GOOD.replace("scale = {", "scael = {"))
    assert "nodes.noise.scael" in message and "did you mean 'scale'" in message


def test_unknown_reference(tmp_path):
    message = error_for(tmp_path, GOOD.replace('param = "scale"', 'param = "scal"'))
    assert "nodes.noise.scale.param" in message and "did you mean 'scale'" in message


def test_default_outside_range(tmp_path):
    message = error_for(tmp_path, GOOD.replace("default = 1.0", "default = 3.0"))
    assert "params.scale.default" in message


def test_missing_param_doc(tmp_path):
    message = error_for(tmp_path, GOOD.replace('doc = "density"\n', ""))
    assert "params.scale.doc" in message


def test_unknown_output_role(tmp_path):
    message = error_for(tmp_path, GOOD.replace('mask = "noise"', 'colour = "noise"'))
    assert "outputs.colour" in message and "did you mean 'color'" in message


def test_bad_enum(tmp_path):
    message = error_for(tmp_path, GOOD.replace('type = "perlin"', 'type = "fbm"\nbasis = "perlni"'))
    assert "nodes.noise.basis" in message and "did you mean 'perlin'" in message


def test_cycle(tmp_path):
    text = """
doc = "cycle"
[nodes.a]
type = "invert"
input = { node = "b" }
[nodes.b]
type = "invert"
input = { node = "a" }
[outputs]
mask = "a"
"""
    assert "cycle" in error_for(tmp_path, text)


def test_invalid_toml(tmp_path):
    assert "g.toml" in error_for(tmp_path, "doc = ")


def test_unknown_graph_and_param():
    with pytest.raises(MapError, match="did you mean 'wood'"):
        load_graph("wod")
    with pytest.raises(MapError, match="did you mean 'grain'"):
        bake({"base_color": {"graph": "wood", "output": "color", "params": {"grian": 1}}}, {}, 16, 0)


def test_param_out_of_range():
    with pytest.raises(MapError, match=r"outside \[0.0, 2.0\]"):
        bake({"base_color": {"graph": "wood", "output": "color", "params": {"grain": 9}}}, {}, 16, 0)
