"""The baking API, size validation and OpenImageIO output."""

import numpy as np
import pytest

from tests.helpers import require

oiio = require("OpenImageIO", "maps")
pytestmark = pytest.mark.oiio

from cnlmc.backends.maps import MapError, bake, validate_size, write_maps  # noqa: E402

REFS = {
    "base_color": {"graph": "wood", "output": "color", "params": {"grain": 1.0}, "seed": 0},
    "normal": {"graph": "wood", "output": "normal", "params": {"grain": 1.0}, "seed": 0},
    "roughness": {"graph": "wood", "output": "roughness", "params": {"grain": 1.0}, "seed": 0},
    "mask": {"graph": "rust", "output": "mask", "params": {}, "seed": 0},
}


@pytest.mark.parametrize("size", [0, 4, 7, 100, 9000, 16384, -64, 64.0, "64", True, None])
def test_validate_size_refuses(size):
    with pytest.raises(MapError):
        validate_size(size)


def test_validate_size_message_suggests():
    with pytest.raises(MapError, match="use 512 or 1024"):
        validate_size(1000)


@pytest.mark.parametrize("size", [8, 64, 1024, 8192])
def test_validate_size_accepts(size):
    assert validate_size(size) == size


def test_bake_roles_and_progress():
    calls = []
    arrays = bake(REFS, {"base_color": [0.8, 0.8, 0.8]}, 32, 1, on_progress=lambda *a: calls.append(a))
    assert set(arrays) == set(REFS)
    assert arrays["base_color"].shape == (32, 32, 3) and arrays["mask"].shape == (32, 32)
    done = [c[0] for c in calls]
    assert done == list(range(1, len(calls) + 1)) and calls[-1][1] == len(calls)
    names = [c[2] for c in calls]
    assert len(names) == len(set(names)), "a node was evaluated twice"


def test_bake_seed_and_determinism():
    a, b, c = bake(REFS, {}, 32, 5), bake(REFS, {}, 32, 5), bake(REFS, {}, 32, 6)
    assert all(np.array_equal(a[r], b[r]) for r in REFS)
    assert not np.array_equal(a["base_color"], c["base_color"])


def test_bad_reference():
    with pytest.raises(MapError, match="no output"):
        bake({"normal": {"graph": "wood", "output": "nromal"}}, {}, 16, 0)


def read(path):
    image = oiio.ImageInput.open(str(path))
    spec, pixels = image.spec(), image.read_image("float")
    image.close()
    return spec, pixels


@pytest.mark.parametrize("fmt,tolerance", [("png8", 1 / 255), ("png16", 1e-4), ("exr-half", 2e-3), ("exr-float", 1e-6)])
def test_round_trip(tmp_path, fmt, tolerance):
    arrays = bake(REFS, {}, 16, 0)
    paths = write_maps(arrays, tmp_path, fmt=fmt, stem="oak")
    assert [p.name.split(".")[0] for p in paths] == [f"oak_{r}" for r in arrays]
    assert not list(tmp_path.glob(".*")), "temporary files left behind"
    for path, (role, array) in zip(paths, arrays.items()):
        spec, pixels = read(path)
        colour_space = spec.get_string_attribute("oiio:ColorSpace")
        if role == "base_color":
            assert same_space(colour_space, "sRGB" if fmt.startswith("png") else "lin_rec709")
        else:
            assert same_space(colour_space, "lin_rec709" if fmt.startswith("png") else "Raw")
        expected = decode(role, pixels, fmt)
        assert np.allclose(expected.reshape(array.shape), array, atol=tolerance * 4), role


def same_space(found, expected):
    """OIIO 3 canonicalises names (sRGB -> srgb_rec709_scene); compare through its config."""
    return found == expected or oiio.ColorConfig().equivalent(found, expected)


def decode(role, pixels, fmt):
    if role == "normal":
        return pixels * 2.0 - 1.0
    if role == "base_color" and fmt.startswith("png"):
        return np.where(pixels <= 0.04045, pixels / 12.92, ((pixels + 0.055) / 1.055) ** 2.4)
    return pixels


def test_unknown_format(tmp_path):
    with pytest.raises(MapError, match="png8"):
        write_maps({"mask": np.zeros((8, 8), np.float32)}, tmp_path, fmt="jpeg")


HOSTILE = "a/../../../ESCAPED"


def test_a_role_that_climbs_out_of_the_folder_is_refused(tmp_path):
    from cnlmc.errors import UsageError

    out = tmp_path / "one" / "two" / "maps"
    out.mkdir(parents=True)
    with pytest.raises(UsageError, match="outside the output folder"):
        write_maps({HOSTILE: np.zeros((8, 8), np.float32)}, out, stem="oak")
    assert sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*")) == ["one", "one/two", "one/two/maps"]


def test_the_baking_service_refuses_a_hostile_role_in_an_ir(tmp_path):
    from cnlmc.backends.maps import bake_files
    from cnlmc.errors import UsageError
    from cnlmc.output import Staging

    material = {"name": "evil", "maps": {HOSTILE: REFS["mask"]}, "params": {}}
    out = tmp_path / "deep" / "maps"
    out.mkdir(parents=True)
    with pytest.raises(UsageError, match="outside the output folder"), Staging(root=out) as staging:
        bake_files(material, out, 16, "png8", 0, staging=staging)
    assert not list(tmp_path.rglob("*ESCAPED*")) and list(out.iterdir()) == []


def test_a_long_stem_keeps_the_role_and_fits(tmp_path):
    paths = write_maps({"mask": np.zeros((8, 8), np.float32)}, tmp_path, stem="s" * 300)
    (name,) = [p.name for p in paths]
    assert len(name.encode()) <= 255 and name.startswith("s" * 100) and name.endswith("_mask.png")
    assert paths[0].is_file()
