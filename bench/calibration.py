"""Calibration against measured data: the phrase a person would type for a measured material, compiled.

Two datasets from the shared data folder (../shared/data next to the repository, or --data DIR):

1. MERL BRDF fits (merl_fits/): 50 of the 100 isotropic materials of the MERL database
   (W. Matusik, H. Pfister, M. Brand, L. McMillan, "A Data-Driven Reflectance Model", ACM TOG
   22(3), SIGGRAPH 2003), as fitted with analytic models and collected by the BSDF benchmark
   bsdfbenchmark/bbm (folder fits/, BSD-3-clause, merl_fits/LICENSE.bbm):
   - low_cooktorrance_E2.fit: J. Löw, J. Kronander, A. Ynnerman, J. Unger, "BRDF models for
     accurate and efficient rendering of glossy surfaces", ACM TOG 31(1), 2012 (Cook–Torrance,
     Beckmann NDF, slope RMS `roughness`; all 50 materials: the reference here);
   - ngan_cooktorrance.fit, ngan_ward.fit: A. Ngan, F. Durand, W. Matusik, "Experimental
     analysis of BRDF models", EGSR 2005 (43 of the 50);
   - bagher_sgd.fit: M. M. Bagher, C. Soler, N. Holzschuch, "Accurate fitting of measured
     reflectances using a Shifted Gamma micro-facet distribution", CGF 31(4), 2012 (per-channel
     alpha; the mean is used).
   Reported: acceptance; metal / non-metal agreement (the truth is by name: alum-bronze,
   aluminium, chrome-steel and ss440 are metals; paints with metallic flakes, hematite and
   silicon nitride are not); Spearman rank correlation between our alpha (the visible lobe's,
   cnlmc IR params.alpha mean, the coat's when coated, 1 for a diffuse-only model) and each
   fit's roughness; hue agreement (fitted colour: the Lambertian albedo, or the specular albedo
   for a metal; both colours scaled to OKLab L = 0.7 first, since MERL albedos are camera RGB of
   arbitrary scale: "agree" = both neutral (C < 0.04), or both chromatic with hue angles within
   35 degrees).

2. physicallybased.info (physicallybased_materials.json, 110 materials; repository
   AntonPalmqvist/physically-based-api, CC0 1.0): acceptance, metal agreement, transmission
   agreement, colour difference CIEDE2000 computed on CIELAB (D65; not on OKLab: CIEDE2000 is
   defined on CIELAB) between their linear-sRGB colour and our apparent colour (base_color,
   times F0 for a conductor), plus the OKLab Euclidean difference ×100 (ΔE_OK) beside it;
   roughness (their value vs our perceptual roughness r of the visible surface: MAE and
   Spearman); IOR (MAE where they give one and our model has one; the dataset uses 1.5 as a
   placeholder for many opaque materials).

Colour maths and the IR readers come from bench/everyday.py (OKLab: Ottosson 2020; CIEDE2000:
Sharma, Wu & Dalal 2005). Spearman: ranks with ties averaged, then Pearson on the ranks
(implemented here with numpy).

    .venv/bin/python bench/calibration.py            # both datasets, summary + per-material tables
    .venv/bin/python bench/calibration.py --summary  # the numbers only
    .venv/bin/python bench/calibration.py --summary --surface-gamut pointer  # + ΔE2000 in Pointer's gamut
Exit status 2 when the shared data folder is missing.
"""

from __future__ import annotations

import argparse
import json
import math
import re
import statistics
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import everyday as ev  # bench/everyday.py: colour maths and IR readers

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT.parent / "shared" / "data"

# MERL name -> (the phrase a person would type, is it a metal)
MERL_PHRASES: dict[str, tuple[str, bool]] = {
    "alum-bronze": ("aluminum bronze", True),
    "aluminium": ("aluminium", True),
    "beige-fabric": ("beige fabric", False),
    "black-obsidian": ("black obsidian", False),
    "black-phenolic": ("black phenolic", False),
    "blue-acrylic": ("blue acrylic", False),
    "blue-metallic-paint": ("blue metallic paint", False),
    "blue-rubber": ("blue rubber", False),
    "cherry-235": ("cherry wood", False),
    "chrome-steel": ("chrome steel", True),
    "color-changing-paint1": ("color changing paint", False),
    "color-changing-paint3": ("dark colour-shifting car paint", False),
    "dark-red-paint": ("dark red paint", False),
    "delrin": ("delrin", False),
    "gold-metallic-paint": ("gold metallic paint", False),
    "gold-metallic-paint3": ("gold metallic car paint", False),
    "gray-plastic": ("gray plastic", False),
    "green-acrylic": ("green acrylic", False),
    "green-latex": ("green latex", False),
    "green-metallic-paint2": ("green metallic paint", False),
    "hematite": ("hematite", False),
    "light-brown-fabric": ("light brown fabric", False),
    "maroon-plastic": ("maroon plastic", False),
    "neoprene-rubber": ("neoprene rubber", False),
    "nylon": ("nylon", False),
    "pearl-paint": ("pearl paint", False),
    "pink-fabric": ("pink fabric", False),
    "pink-felt": ("pink felt", False),
    "pink-plastic": ("pink plastic", False),
    "polyurethane-foam": ("polyurethane foam", False),
    "purple-paint": ("purple paint", False),
    "red-fabric": ("red fabric", False),
    "red-metallic-paint": ("red metallic paint", False),
    "red-plastic": ("red plastic", False),
    "silicon-nitrade": ("silicon nitride", False),
    "silver-metallic-paint2": ("silver metallic paint", False),
    "special-walnut-224": ("special walnut", False),
    "specular-blue-phenolic": ("glossy blue phenolic", False),
    "specular-maroon-phenolic": ("glossy maroon phenolic", False),
    "specular-red-phenolic": ("glossy red phenolic", False),
    "specular-white-phenolic": ("glossy white phenolic", False),
    "ss440": ("stainless steel", True),
    "teflon": ("teflon", False),
    "two-layer-gold": ("gold car paint", False),
    "violet-acrylic": ("violet acrylic", False),
    "white-acrylic": ("white acrylic", False),
    "white-fabric": ("white fabric", False),
    "white-marble": ("white marble", False),
    "yellow-matte-plastic": ("yellow matte plastic", False),
    "yellow-phenolic": ("yellow phenolic", False),
}

# physicallybased.info name -> phrase, where lower-casing and "Name (Kind)" -> "kind name" is not it
PB_PHRASES = {
    "Aluminum (Anodized Red)": "red anodized aluminum",
    "Beer (Pale Lager)": "pale lager",
    "Egg Shell (Brown)": "brown eggshell",
    "Egg Shell (White)": "white eggshell",
    "Eye (Cornea)": "cornea",
    "Eye (Lens)": "eye lens",
    "Eye (Sclera)": "white of the eye",
    "Orange": "orange peel",  # plain 'orange' is the colour
    "Plastic (Acrylic)": "clear acrylic",
    "Plastic (PC)": "clear polycarbonate",
    "Plastic (PET)": "clear PET plastic",
    "Plastic (PP)": "clear polypropylene",
    "Plastic (PUR)": "clear polyurethane",
    "Plastic (PVC)": "clear PVC",
    "Polystyrene (Foam)": "polystyrene foam",
    "Skin I": "very fair skin",
    "Skin II": "fair skin",
    "Skin III": "medium skin",
    "Skin IV": "olive skin",
    "Skin V": "brown skin",
    "Skin VI": "dark brown skin",
    "Gray Card": "grey card",
}

SPECULAR_KEYS = ("LowCookTorrance", "NganCookTorrance", "NganWard", "Bagher")
FITS = {
    "low": "low_cooktorrance_E2.fit",
    "ngan_ct": "ngan_cooktorrance.fit",
    "ngan_ward": "ngan_ward.fit",
    "bagher": "bagher_sgd.fit",
}


# ------------------------------------------------------------------------------------ helpers


def ranks(x: Sequence[float]) -> np.ndarray:
    """Ranks 1..n with ties given their average rank."""
    a = np.asarray(x, dtype=float)
    order = np.argsort(a, kind="mergesort")
    r = np.empty(len(a))
    r[order] = np.arange(1, len(a) + 1)
    for v in np.unique(a):
        tie = a == v
        if tie.sum() > 1:
            r[tie] = r[tie].mean()
    return r


def spearman(x: Sequence[float], y: Sequence[float]) -> float:
    """Spearman's rank correlation (Pearson on tie-averaged ranks); nan for fewer than 3 pairs."""
    if len(x) < 3:
        return math.nan
    rx, ry = ranks(x), ranks(y)
    rx, ry = rx - rx.mean(), ry - ry.mean()
    d = math.sqrt(float((rx * rx).sum() * (ry * ry).sum()))
    return float((rx * ry).sum() / d) if d else math.nan


def scaled_to_lightness(rgb: Sequence[float], target: float = 0.7) -> tuple[float, float, float]:
    """The colour scaled (linear RGB times k) so that its OKLab L is `target` (L scales with k^(1/3))."""
    L = ev.oklab(rgb)[0]
    if L <= 1e-6:
        return (0.0, 0.0, 0.0)
    k = (target / L) ** 3
    return (rgb[0] * k, rgb[1] * k, rgb[2] * k)


def hue_agrees(a: Sequence[float], b: Sequence[float]) -> bool:
    """Broad hue agreement of two colours of any scale (see the docstring)."""
    _, ca, ha = ev.oklch(scaled_to_lightness(a))
    _, cb, hb = ev.oklch(scaled_to_lightness(b))
    na, nb = ca < ev.NEUTRAL_CHROMA, cb < ev.NEUTRAL_CHROMA
    if na or nb:
        return na and nb
    return abs((ha - hb + 180) % 360 - 180) <= 35


def compile_phrase(phrase: str) -> tuple[dict[str, Any] | None, str]:
    from cnlmc import api

    result = api.compile_source(phrase, "<calibration>", api.lexicon_for())
    errors = [f"{d.code} {d.message}" for d in result.diagnostics if d.is_error]
    if errors or not result.materials:
        return None, (errors or ["E003 no material"])[0]
    return result.materials[0], ""


def fmt(x: float, digits: int = 3) -> str:
    return "   -" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{digits}f}"


# ------------------------------------------------------------------------------------- MERL

_FIT_LINE = re.compile(r"^([\w.-]+) = Aggregate\(Lambertian\(albedo = \[([^\]]*)\]\), (\w+)\((.*)\)\)\s*$")


def parse_fit(path: Path) -> dict[str, dict[str, Any]]:
    """A bbm .fit file -> name -> {diffuse: [r,g,b], model, albedo, roughness (a float), eta}."""
    out: dict[str, dict[str, Any]] = {}
    for line in path.read_text("utf-8").splitlines():
        m = _FIT_LINE.match(line.strip())
        if not m:
            continue
        name, diffuse, model, args = m.groups()
        rec: dict[str, Any] = {"diffuse": [float(v) for v in diffuse.split(",")], "model": model}
        alb = re.search(r"\balbedo = \[([^\]]*)\]", args)
        rec["albedo"] = [float(v) for v in alb.group(1).split(",")] if alb else None
        rough = re.search(r"\broughness = ([-\d.eE+]+)", args)
        alpha = re.search(r"\balpha = \[([^\]]*)\]", args)
        if rough:
            rec["roughness"] = float(rough.group(1))
        elif alpha:  # Bagher: per-channel alpha
            rec["roughness"] = statistics.fmean(float(v) for v in alpha.group(1).split(","))
        out[name] = rec
    return out


def merl(data: Path, verbose: bool) -> dict[str, Any]:
    folder = data / "merl_fits"
    fits = {key: parse_fit(folder / name) for key, name in FITS.items()}
    names = sorted(fits["low"])
    rows = []
    for name in names:
        phrase, metal = MERL_PHRASES.get(name, (name.replace("-", " "), False))
        m, error = compile_phrase(phrase)
        row: dict[str, Any] = {"name": name, "phrase": phrase, "metal": metal, "error": error}
        if m is not None:
            low = fits["low"][name]
            fitted_colour = low["albedo"] if metal else low["diffuse"]
            row |= {
                "ours_metal": m["model"]["base"] == "conductor",
                "alpha": ev.effective_alpha(m),
                "hue_ok": hue_agrees(fitted_colour, ev.apparent_colour(m)),
                "ours_hex": ev.linear_to_hex(scaled_to_lightness(ev.apparent_colour(m))),
                "fit_hex": ev.linear_to_hex(scaled_to_lightness(fitted_colour)),
            }
        for key in FITS:
            row[key] = fits[key].get(name, {}).get("roughness")
        rows.append(row)
    ok = [r for r in rows if not r["error"]]
    summary: dict[str, Any] = {
        "materials": len(rows),
        "accepted": len(ok),
        "metal_agreement": sum(r["ours_metal"] == r["metal"] for r in ok),
        "hue_agreement": sum(r["hue_ok"] for r in ok),
    }
    for key in FITS:
        pairs = [(r["alpha"], r[key]) for r in ok if r[key] is not None]
        summary[f"spearman_{key}"] = spearman([p[0] for p in pairs], [p[1] for p in pairs])
        summary[f"n_{key}"] = len(pairs)
    print("MERL (50 materials; fits: Löw 2012 CT-E2, Ngan 2005 CT and Ward, Bagher 2012 SGD)")
    n = summary["materials"]
    print(f"  accepted              {summary['accepted']}/{n}")
    k = summary["accepted"]
    print(f"  metal class agrees    {summary['metal_agreement']}/{k} accepted")
    print(f"  hue agrees            {summary['hue_agreement']}/{k} accepted")
    for key, label in (("low", "Löw CT Beckmann m"), ("ngan_ct", "Ngan CT Beckmann m"), ("ngan_ward", "Ngan Ward α")):
        print(f"  Spearman(our α, {label:<20}) = {fmt(summary[f'spearman_{key}'])}  (n = {summary[f'n_{key}']})")
    print(f"  Spearman(our α, Bagher SGD mean α   ) = {fmt(summary['spearman_bagher'])}  (n = {summary['n_bagher']})")
    summary["goals_met"] = merl_goals_met(summary)
    print(f"  goals (issue #14: all accepted, metal class 100 %, Spearman(Löw) >= 0.75): {summary['goals_met']}")
    if verbose:
        print(f"\n  {'MERL name':<26}{'phrase':<32}{'metal':>6}{'ours':>6}{'our α':>8}{'Löw m':>8}  hue (fit / ours)")
        for r in rows:
            if r["error"]:
                print(f"  {r['name']:<26}{r['phrase']:<32}{'REJECTED: ' + r['error']}")
                continue
            hue = f"{'ok ' if r['hue_ok'] else 'NO '} {r['fit_hex']} / {r['ours_hex']}"
            print(
                f"  {r['name']:<26}{r['phrase']:<32}{'yes' if r['metal'] else 'no':>6}"
                f"{'yes' if r['ours_metal'] else 'no':>6}{fmt(r['alpha']):>8}{fmt(r['low']):>8}  {hue}"
            )
    return {"summary": summary, "rows": rows}


def merl_goals_met(summary: dict[str, Any]) -> bool:
    """Issue #14's calibration goals: every MERL phrase accepted, the metal class right for every
    one, and Spearman(our alpha, Löw's Beckmann m) >= 0.75."""
    every = summary["accepted"] == summary["materials"]
    metals = summary["metal_agreement"] == summary["accepted"]
    return bool(every and metals and summary["spearman_low"] >= MERL_SPEARMAN_GOAL)


MERL_SPEARMAN_GOAL = 0.75


# --------------------------------------------------------------------------- physicallybased


def pb_phrase(name: str) -> str:
    if name in PB_PHRASES:
        return PB_PHRASES[name]
    m = re.fullmatch(r"(.*) \((.*)\)", name)
    return f"{m.group(2)} {m.group(1)}".lower() if m else name.lower()


def srgb_linear(entry: dict[str, Any]) -> list[float] | None:
    for c in entry.get("color") or []:
        if c.get("colorSpace") == "srgb-linear":
            return [float(v) for v in c["color"]]
    return None


def physicallybased(data: Path, verbose: bool, gamut: str = "none") -> dict[str, Any]:
    """The physicallybased.info comparison; with gamut "pointer" also ΔE2000 with our pigment colours
    mapped into Pointer's gamut of real surface colours (bench/surface_gamut.py, issue #15)."""
    items = json.loads((data / "physicallybased_materials.json").read_text("utf-8"))["data"]
    rows = []
    for item in items:
        phrase = pb_phrase(item["name"])
        m, error = compile_phrase(phrase)
        row: dict[str, Any] = {"name": item["name"], "phrase": phrase, "error": error}
        colour = srgb_linear(item)
        row["metal"] = bool(item.get("metalness"))
        row["transmissive"] = bool(item.get("transmission"))
        if m is not None:
            ours = ev.apparent_colour(m)
            row |= {
                "ours_metal": m["model"]["base"] == "conductor",
                "ours_transmissive": m["model"]["base"] == "glass",
                "roughness": item.get("roughness"),
                "ours_roughness": ev.effective_roughness(m),
                "ior": item.get("ior"),
                "ours_ior": m["params"].get("ior"),
            }
            if colour is not None:
                row["de2000"] = ev.delta_e2000(ev.cielab(colour), ev.cielab(ours))
                row["de_ok"] = 100 * math.dist(ev.oklab(colour), ev.oklab(ours))
                row["hex"], row["ours_hex"] = ev.linear_to_hex(colour), ev.linear_to_hex(ours)
                if gamut == "pointer":
                    row |= pointer_colour(m, colour)
        rows.append(row)
    ok = [r for r in rows if not r["error"]]
    de = [r["de2000"] for r in ok if "de2000" in r]
    de_ok = [r["de_ok"] for r in ok if "de_ok" in r]
    rough = [(r["ours_roughness"], r["roughness"]) for r in ok if r.get("roughness") is not None]
    iors = [(r["ours_ior"], r["ior"]) for r in ok if r.get("ior") is not None and r.get("ours_ior") is not None]
    summary = {
        "materials": len(rows),
        "accepted": len(ok),
        "metal_agreement": sum(r["ours_metal"] == r["metal"] for r in ok),
        "transmission_agreement": sum(r["ours_transmissive"] == r["transmissive"] for r in ok),
        "de2000_median": statistics.median(de) if de else math.nan,
        "de2000_le_10": sum(d <= 10 for d in de),
        "de_ok_median": statistics.median(de_ok) if de_ok else math.nan,
        "roughness_mae": statistics.fmean(abs(a - b) for a, b in rough) if rough else math.nan,
        "roughness_spearman": spearman([a for a, _ in rough], [b for _, b in rough]),
        "n_roughness": len(rough),
        "ior_mae": statistics.fmean(abs(a - b) for a, b in iors) if iors else math.nan,
        "n_ior": len(iors),
    }
    k = summary["accepted"]
    print("\nphysicallybased.info (110 materials, CC0)")
    print(f"  accepted              {k}/{summary['materials']}")
    print(f"  metal class agrees    {summary['metal_agreement']}/{k} accepted")
    print(f"  transmission agrees   {summary['transmission_agreement']}/{k} accepted")
    print(
        f"  colour CIEDE2000 (CIELAB D65)  median {fmt(summary['de2000_median'], 1)}, "
        f"<= 10: {summary['de2000_le_10']}/{len(de)};  OKLab ΔE_OK×100 median {fmt(summary['de_ok_median'], 1)}"
    )
    print(
        f"  roughness  MAE {fmt(summary['roughness_mae'])}, Spearman {fmt(summary['roughness_spearman'])}"
        f"  (n = {summary['n_roughness']})"
    )
    print(f"  IOR        MAE {fmt(summary['ior_mae'])}  (n = {summary['n_ior']})")
    if gamut == "pointer":
        summary |= pointer_summary(ok)
    if verbose:
        print(
            f"\n  {'name':<28}{'phrase':<28}{'metal':>6}{'ours':>6}{'ΔE00':>7}{'r':>6}{'our r':>7}{'ior':>7}{'ours':>7}"
        )
        for r in rows:
            if r["error"]:
                print(f"  {r['name']:<28}{r['phrase']:<28}REJECTED: {r['error']}")
                continue
            print(
                f"  {r['name']:<28}{r['phrase']:<28}{'yes' if r['metal'] else 'no':>6}"
                f"{'yes' if r['ours_metal'] else 'no':>6}{fmt(r.get('de2000'), 1):>7}"
                f"{fmt(r.get('roughness'), 2):>6}{fmt(r.get('ours_roughness'), 2):>7}"
                f"{fmt(r.get('ior'), 3):>7}{fmt(r.get('ours_ior'), 3):>7}"
            )
    return {"summary": summary, "rows": rows}


def pointer_colour(m: dict[str, Any], colour: Sequence[float]) -> dict[str, Any]:
    """ΔE2000 of their colour against ours with the pigment colours in Pointer's gamut."""
    from surface_gamut import in_surface_gamut

    ours = ev.apparent_colour(in_surface_gamut(m))
    moved = ours != ev.apparent_colour(m)
    return {"de2000_pointer": ev.delta_e2000(ev.cielab(colour), ev.cielab(ours)), "pointer_moved": moved}


def pointer_summary(ok: Sequence[dict[str, Any]]) -> dict[str, Any]:
    """ΔE2000 with and without Pointer's gamut: all coloured rows, and the rows whose colour moved."""
    rows = [r for r in ok if "de2000_pointer" in r]
    moved = [r for r in rows if r["pointer_moved"]]
    summary = {
        "de2000_median_pointer": statistics.median(r["de2000_pointer"] for r in rows) if rows else math.nan,
        "n_pointer_moved": len(moved),
        "pointer_closer": sum(r["de2000_pointer"] < r["de2000"] for r in moved),
        "pointer_further": sum(r["de2000_pointer"] > r["de2000"] for r in moved),
    }
    print(
        f"  in Pointer's gamut: ΔE2000 median {fmt(summary['de2000_median_pointer'], 1)} (all {len(rows)} coloured);"
        f" colour moved for {len(moved)}: {summary['pointer_closer']} closer, {summary['pointer_further']} further"
    )
    if moved:
        before = statistics.median(r["de2000"] for r in moved)
        after = statistics.median(r["de2000_pointer"] for r in moved)
        print(f"    the moved ones: ΔE2000 median {before:.1f} -> {after:.1f}")
    for r in sorted(moved, key=lambda r: r["de2000_pointer"] - r["de2000"]):
        print(
            f"    {r['name']:<28}{r['phrase']:<28}{r['hex']} vs {r['ours_hex']}: {r['de2000']:5.1f} -> {r['de2000_pointer']:5.1f}"
        )
    return summary


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--data", type=Path, default=DATA, help="the shared data folder (default ../shared/data)")
    ap.add_argument("--summary", action="store_true", help="the numbers only, no per-material tables")
    ap.add_argument("--json", type=Path, help="write the summaries and rows as JSON")
    ap.add_argument(
        "--surface-gamut",
        choices=("none", "pointer"),
        default="none",
        help="pointer: also ΔE2000 with our pigment colours in Pointer's gamut (bench/surface_gamut.py)",
    )
    args = ap.parse_args(argv)
    needed = [args.data / "merl_fits" / name for name in FITS.values()]
    needed.append(args.data / "physicallybased_materials.json")
    missing = [str(p) for p in needed if not p.exists()]
    if missing:
        print(
            f"calibration: the shared data folder is missing ({', '.join(missing)}); pass --data DIR", file=sys.stderr
        )
        return 2
    out = {
        "merl": merl(args.data, not args.summary),
        "physicallybased": physicallybased(args.data, not args.summary, args.surface_gamut),
    }
    if args.json:
        args.json.write_text(json.dumps(out, indent=1, ensure_ascii=False, default=float))
    return 0


if __name__ == "__main__":
    sys.exit(main())
