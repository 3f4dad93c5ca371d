"""Graph parameters move the maps in the direction their names promise."""

import numpy as np

from cnlmc.backends.maps import evaluate, load_graph

from .conftest import luminance

SIZE = 128


def bake(name, output, seed=3, **params):
    return evaluate(load_graph(name), SIZE, seed=seed, params=params, outputs=[output])[output]


def normal_tilt(normal):
    return float(np.mean(1.0 - normal[..., 2]))


def test_lower_grain_lowers_wood_contrast():
    low, high = (luminance(bake("wood", "color", grain=g)).std() for g in (0.3, 1.5))
    assert low < high


def test_higher_contrast_darkens_latewood():
    soft, hard = (luminance(bake("wood", "color", contrast=c)) for c in (0.3, 1.8))
    assert soft.std() < hard.std()


def test_more_coverage_more_rust():
    means = [bake("rust", "mask", coverage=c).mean() for c in (0.1, 0.4, 0.8)]
    assert means[0] < means[1] < means[2]
    assert abs(means[1] - 0.4) < 0.05


def test_rust_lowers_metallic_and_raises_roughness():
    rusty = evaluate(load_graph("rust"), SIZE, params={"coverage": 0.9}, material={"roughness": 0.2})
    assert rusty["metallic"].mean() < 0.2
    assert rusty["roughness"].mean() > 0.6


def test_strength_tilts_normals(graph_name):
    graph = load_graph(graph_name)
    if "strength" not in graph.params or "normal" not in graph.outputs:
        return
    weak, strong = (normal_tilt(bake(graph_name, "normal", strength=s)) for s in (0.2, 2.0))
    assert weak < strong


def test_zero_strength_is_flat():
    assert np.allclose(bake("brushed", "normal", strength=0.0)[..., 2], 1.0)


def test_brushed_direction_turns_streaks():
    along_u = bake("brushed", "mask", direction=0.0)
    along_v = bake("brushed", "mask", direction=90.0)
    # streaks along u: neighbours along u are similar, across are not
    assert np.abs(np.diff(along_u, axis=1)).mean() < np.abs(np.diff(along_u, axis=0)).mean()
    assert np.abs(np.diff(along_v, axis=0)).mean() < np.abs(np.diff(along_v, axis=1)).mean()


def test_finer_scale_has_more_detail():
    coarse, fine = (bake("hammered", "mask", scale=s) for s in (0.5, 2.0))
    assert np.abs(np.diff(coarse, axis=1)).mean() < np.abs(np.diff(fine, axis=1)).mean()


def test_colour_comes_from_material():
    white = evaluate(load_graph("wood"), SIZE, material={"base_color": [0.9, 0.9, 0.88]}, outputs=["color"])["color"]
    brown = evaluate(load_graph("wood"), SIZE, material={"base_color": [0.4, 0.2, 0.1]}, outputs=["color"])["color"]
    assert white.mean() > brown.mean()
    assert abs(white[..., 0].mean() - white[..., 2].mean()) < 0.05


def test_presets_apply():
    pine = evaluate(load_graph("wood"), SIZE, params={"preset": "pine"}, outputs=["color"])["color"]
    maple = evaluate(load_graph("wood"), SIZE, params={"preset": "maple"}, outputs=["color"])["color"]
    assert luminance(pine).std() > luminance(maple).std()
