"""Real surface colours are bounded: a base colour mapped into Pointer's gamut (issue #15's experiment).

M. R. Pointer, "The gamut of real surface colours", Color Research & Application 5(3), 1980,
tabulates the largest CIELAB chroma C*ab of real (non-fluorescent) surfaces per lightness L* and hue
angle h_ab (stdlib/data/pointer_gamut.toml). A colour outside it is brighter-than-paint: a monitor
colour, not a surface's. `to_surface_gamut` keeps a colour's L* and h_ab and limits its C*ab to the
table's bound; `in_surface_gamut` applies that to the pigment colours of a compiled material.

Colorimetry: the table's CIELAB uses CIE illuminant C as its white (2° observer). A linear-sRGB
colour (D65) is converted to XYZ (IEC 61966-2-1 matrix), adapted D65 -> C with the Bradford
transform (K. M. Lam, thesis, University of Bradford 1985; its linear form, the one ICC profiles use:
a von Kries gain on the cone-like responses M_BFD below), then to CIELAB with C's white; the way back reverses
each step. The bound between table points is bilinear in L* and h_ab (h periodic); below L* 15 and
above L* 90, where Pointer tabulated nothing, it falls linearly to 0 at L* 0 and L* 100 (our
assumption: black and white have no chroma).

Which colours: base_color and sheen_color of a pigmented surface (model base "dielectric" or
"diffuse"). Left alone: a conductor's colour and F0 (a metal's tint is not a pigment), glass (a
transmittance, not a surface reflectance), a coat's colour (a filter), metallic flakes' colour (metal
tints) and a subsurface medium's colour.

    .venv/bin/python bench/surface_gamut.py "blue rubber" "pink felt"   # L*, C*, h, bound, mapped
"""

from __future__ import annotations

import copy
import math
import sys
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
TABLE = ROOT / "stdlib" / "data" / "pointer_gamut.toml"

SRGB_TO_XYZ = np.array(
    [[0.4124564, 0.3575761, 0.1804375], [0.2126729, 0.7151522, 0.0721750], [0.0193339, 0.1191920, 0.9503041]]
)
D65_XYZ = np.array([0.95047, 1.0, 1.08883])
M_BFD = np.array([[0.8951, 0.2664, -0.1614], [-0.7502, 1.7135, 0.0367], [0.0389, -0.0685, 1.0296]])
PIGMENTED_BASES = ("dielectric", "diffuse")
PIGMENT_KEYS = ("base_color", "sheen_color")
CHROMA_TOLERANCE = 0.01  # C*ab: a white's rounding chroma at L* 100, where the bound is 0, is not "outside"


def xy_to_xyz(xy: Sequence[float]) -> np.ndarray:
    """A white's chromaticity -> its XYZ with Y = 1."""
    x, y = float(xy[0]), float(xy[1])
    return np.array([x / y, 1.0, (1.0 - x - y) / y])


def bradford(source_white: np.ndarray, target_white: np.ndarray) -> np.ndarray:
    """The 3×3 linear Bradford adaptation XYZ(source white) -> XYZ(target white)."""
    gain = (M_BFD @ target_white) / (M_BFD @ source_white)
    return np.asarray(np.linalg.inv(M_BFD) @ np.diag(gain) @ M_BFD, float)


def _f(t: np.ndarray) -> np.ndarray:
    d = 6 / 29
    return np.where(t > d**3, np.cbrt(t), t / (3 * d * d) + 4 / 29)


def _f_inverse(t: np.ndarray) -> np.ndarray:
    d = 6 / 29
    return np.where(t > d, t**3, 3 * d * d * (t - 4 / 29))


def xyz_to_lab(xyz: np.ndarray, white: np.ndarray) -> np.ndarray:
    fx, fy, fz = _f(np.asarray(xyz) / white)
    return np.array([116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)])


def lab_to_xyz(lab: np.ndarray, white: np.ndarray) -> np.ndarray:
    fy = (lab[0] + 16) / 116
    return np.asarray(white * _f_inverse(np.array([fy + lab[1] / 500, fy, fy - lab[2] / 200])), float)


@dataclass(frozen=True)
class SurfaceGamut:
    """Pointer's table: the largest C*ab at each (L*, h_ab) grid point, and the table's white."""

    lightness: np.ndarray  # (nL,)
    hue: np.ndarray  # (nh,), degrees, evenly spaced from 0
    max_chroma: np.ndarray  # (nL, nh)
    white: np.ndarray  # XYZ of the table's illuminant, Y = 1

    def bound(self, lightness: float, hue: float) -> float:
        """The largest C*ab of a real surface at (L*, h_ab): bilinear, h periodic, 0 at L* 0 and 100."""
        step = float(self.hue[1] - self.hue[0])
        t = (hue % 360.0) / step
        j = int(math.floor(t)) % len(self.hue)
        u = t - math.floor(t)
        around = (1 - u) * self.max_chroma[:, j] + u * self.max_chroma[:, (j + 1) % len(self.hue)]
        ls = np.concatenate([[0.0], self.lightness, [100.0]])
        cs = np.concatenate([[0.0], around, [0.0]])
        return float(np.interp(lightness, ls, cs))

    def adapt_in(self) -> np.ndarray:
        """Linear sRGB (D65) -> XYZ under the table's illuminant."""
        return np.asarray(bradford(D65_XYZ, self.white) @ SRGB_TO_XYZ, float)

    def lch(self, rgb: Sequence[float]) -> tuple[float, float, float]:
        """Linear sRGB -> (L*, C*ab, h_ab degrees) in the table's CIELAB."""
        lab = xyz_to_lab(self.adapt_in() @ np.clip(np.asarray(rgb, float), 0.0, None), self.white)
        return float(lab[0]), float(math.hypot(lab[1], lab[2])), math.degrees(math.atan2(lab[2], lab[1])) % 360.0

    def to_surface_gamut(self, rgb: Sequence[float]) -> tuple[float, float, float]:
        """The colour with its C*ab limited to Pointer's bound (L* and h_ab kept); unchanged when inside."""
        lightness, chroma, hue = self.lch(rgb)
        limit = self.bound(lightness, hue)
        if chroma <= limit + CHROMA_TOLERANCE:
            return (float(rgb[0]), float(rgb[1]), float(rgb[2]))
        h = math.radians(hue)
        lab = np.array([lightness, limit * math.cos(h), limit * math.sin(h)])
        out = np.linalg.solve(self.adapt_in(), lab_to_xyz(lab, self.white))
        r, g, b = np.clip(out, 0.0, 1.0)
        return (float(r), float(g), float(b))


@cache
def pointer_gamut(path: Path = TABLE) -> SurfaceGamut:
    """stdlib/data/pointer_gamut.toml, read once."""
    table = tomllib.loads(path.read_text("utf-8"))["pointer_1980"]
    return SurfaceGamut(
        np.asarray(table["lightness"], float),
        np.asarray(table["hue"], float),
        np.asarray(table["max_chroma"], float),
        xy_to_xyz(table["white_xy"]),
    )


def in_surface_gamut(material: Mapping[str, Any], gamut: SurfaceGamut | None = None) -> dict[str, Any]:
    """A copy of a compiled material whose pigment colours (see the docstring) lie in Pointer's gamut."""
    out = copy.deepcopy(dict(material))
    if out["model"]["base"] not in PIGMENTED_BASES:
        return out
    gamut = gamut or pointer_gamut()
    for key in PIGMENT_KEYS:
        colour = out["params"].get(key)
        if colour is not None:
            out["params"][key] = list(gamut.to_surface_gamut(colour))
    return out


def main(argv: Sequence[str]) -> int:
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import calibration as cal

    gamut = pointer_gamut()
    for phrase in argv:
        material, error = cal.compile_phrase(phrase)
        if material is None:
            print(f"{phrase}: {error}")
            continue
        base = material["params"]["base_color"]
        lightness, chroma, hue = gamut.lch(base)
        mapped = in_surface_gamut(material, gamut)["params"]["base_color"]
        print(
            f"{phrase:<28} L* {lightness:5.1f}  C* {chroma:6.1f}  h {hue:5.1f}  bound {gamut.bound(lightness, hue):5.1f}"
            f"  {[round(c, 4) for c in base]} -> {[round(c, 4) for c in mapped]}"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
