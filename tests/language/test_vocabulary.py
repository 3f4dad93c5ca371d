"""The noun vocabulary (issue #14 part 2): large, documented, and grounded in the reference data.

Every noun has a doc line, an example and a `source`; the example compiles and names the noun;
every dataset file a source names exists; values a source cites verbatim match the dataset row
(when ../shared/data is beside the checkout; CI has no copy, so those tests skip).

A verbatim citation reads `FILE 'ROW' [field, field, ...]` (e.g. physicallybased_materials.json
'Sand' [base_color, roughness]); the metals keep the form `metals_rgb.json: KEY, dataset NAME`,
whose eta, k and f0 are that dataset's RGB fits and F0, and f82 its F82 (the primary dataset) or
the exact Fresnel reflectance of its eta/k at acos(1/7) (an alternative dataset).
"""

from __future__ import annotations

import cmath
import json
import math
import re
from pathlib import Path
from typing import Any

import pytest

from cnlmc.api import compile_source

DATA = Path(__file__).resolve().parents[3] / "shared" / "data"

#: The reference datasets of ../shared/data (its README's table) a `source` may name.
KNOWN_DATASETS = frozenset(
    {
        "metals_rgb.json",
        "metals_rgb.csv",
        "dielectrics.json",
        "dielectrics_ior.csv",
        "dielectrics_physicallybased.csv",
        "physicallybased_materials.json",
        "brdf_accuracy_checks.json",
        "merl_fits/low_cooktorrance_E2.fit",
        "merl_fits/ngan_cooktorrance.fit",
        "merl_fits/ngan_ward.fit",
        "merl_fits/bagher_sgd.fit",
    }
)
DATASET_NAME = re.compile(r"[\w./-]+\.(?:json|csv|fit)\b")
CITATION = re.compile(r"([\w./-]+\.(?:json|csv)) '([^']+)' \[([^\]]+)\]")
METAL_CITATION = re.compile(r"metals_rgb\.json: ([\w-]+), dataset ([\w-]+)")
FREE_PB_ROW = re.compile(r"physicallybased\.info '([^']+)'")
MU_82 = 1 / 7  # cos of the F82 angle
TOLERANCE = 5e-4  # the stdlib keeps four decimals


def nouns_named(material: dict[str, Any]) -> set[str]:
    """The noun entries whose values a compiled material carries (its provenance rules)."""
    rules = (step["rule"] for steps in material["provenance"].values() for step in steps)
    return {rule.removeprefix("nouns.").split(".")[0] for rule in rules if rule.startswith("nouns.")}


def fresnel(n: float, k: float, mu: float) -> float:
    """Unpolarised Fresnel reflectance of a conductor (eta = n + ik) from air at cos(theta) = mu."""
    eta = complex(n, k)
    cos_t = cmath.sqrt(1 - (1 - mu * mu) / (eta * eta))
    rs = (mu - eta * cos_t) / (mu + eta * cos_t)
    rp = (eta * mu - cos_t) / (eta * mu + cos_t)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def close(ours: Any, theirs: Any) -> bool:
    if isinstance(ours, list) or isinstance(theirs, list):
        ours_list = ours if isinstance(ours, list) else [ours] * len(theirs)
        theirs_list = theirs if isinstance(theirs, list) else [theirs] * len(ours)
        return len(ours_list) == len(theirs_list) and all(map(close, ours_list, theirs_list))
    return theirs is not None and math.isclose(float(ours), float(theirs), abs_tol=TOLERANCE)


def nouns(stdlib):
    return stdlib.all_of("nouns")


# ---------------------------------------------------------------- every noun, no data needed


def test_the_stdlib_has_at_least_150_nouns(stdlib):
    assert len(nouns(stdlib)) >= 150


def test_every_noun_has_doc_example_and_source(stdlib):
    for key, entry in nouns(stdlib).items():
        assert "." not in key, key  # provenance rules read nouns.KEY[.part]
        for field in ("doc", "example", "source"):
            assert isinstance(entry.get(field), str) and entry.get(field).strip(), (key, field)


def test_every_noun_compiles_alone_and_its_example_names_it(stdlib):
    for key, entry in nouns(stdlib).items():
        for text in (key, entry.get("example")):
            result = compile_source(text, "example.cnl", stdlib)
            assert result.ok, (key, text, [d.message for d in result.diagnostics])
            assert key in nouns_named(result.materials[0]), (key, text, nouns_named(result.materials[0]))


def test_every_alias_compiles_alone_and_names_its_noun_only(stdlib):
    for key, entry in nouns(stdlib).items():
        for alias in entry.get("aliases", []):
            result = compile_source(alias, "alias.cnl", stdlib)
            assert result.ok, (key, alias, [d.message for d in result.diagnostics])
            assert nouns_named(result.materials[0]) == {key}, (key, alias, nouns_named(result.materials[0]))


def test_every_source_names_a_known_dataset_or_says_the_value_is_our_choice(stdlib):
    for key, entry in nouns(stdlib).items():
        source = entry.get("source")
        named = DATASET_NAME.findall(source)
        assert set(named) <= KNOWN_DATASETS, (key, sorted(set(named) - KNOWN_DATASETS))
        assert named or "our choice" in source, key


def test_cited_fields_are_the_entrys_fields(stdlib):
    for key, entry in nouns(stdlib).items():
        for _file, _row, fields in CITATION.findall(entry.get("source")):
            for field in (f.strip() for f in fields.split(",")):
                assert entry.get(field) is not None, (key, field)


@pytest.mark.parametrize(
    "spelling,key",
    [
        ("carbon fiber", "carbon fibre"),
        ("fibreglass", "fiberglass"),
        ("aluminium", "aluminum"),
        ("aluminium bronze", "aluminum bronze"),
        ("fibre cement", "fiber cement"),
        ("microfibre", "microfiber"),
        ("grey card", "gray card"),
        ("plexiglas", "plexiglass"),
    ],
)
def test_british_and_american_spellings_name_one_noun(stdlib, spelling, key):
    result = compile_source(spelling, "spelling.cnl", stdlib)
    assert result.ok and nouns_named(result.materials[0]) == {key}


@pytest.mark.parametrize(
    "phrase,key",
    [
        ("white oak", "white oak"),
        ("oiled white oak", "white oak"),
        ("honed carrara marble", "carrara marble"),
        ("brushed stainless steel", "stainless steel"),
        ("black walnut", "walnut"),
        ("linen fabric", "linen"),
        ("reclaimed barn wood", "barn wood"),
    ],
)
def test_multi_word_nouns_are_matched_whole(stdlib, phrase, key):
    result = compile_source(phrase, "multi.cnl", stdlib)
    assert result.ok and key in nouns_named(result.materials[0]), [d.message for d in result.diagnostics]


def test_every_metals_f82_agrees_with_its_own_eta_and_k(stdlib):
    """f82 is measured (spectral) or computed from eta/k: within 0.01 of the exact Fresnel of eta/k either way."""
    for key, entry in nouns(stdlib).items():
        if entry.get("model") == "conductor":
            exact = [fresnel(n, k, MU_82) for n, k in zip(entry.get("eta"), entry.get("k"))]
            assert all(math.isclose(a, b, abs_tol=0.01) for a, b in zip(entry.get("f82"), exact)), (key, exact)


def test_clear_plastics_transmit_and_pigmented_ones_do_not(stdlib):
    model = {key: entry.get("model") for key, entry in nouns(stdlib).items()}
    assert {model[k] for k in ("plexiglass", "polycarbonate", "pet plastic", "epoxy resin")} == {"glass"}
    assert {model[k] for k in ("pvc", "vinyl", "nylon", "abs", "melamine", "phenolic")} == {"dielectric"}


# ---------------------------------------------------------------- values against ../shared/data


class Data:
    """The reference datasets, read once."""

    def __init__(self, folder: Path) -> None:
        pb = json.loads((folder / "physicallybased_materials.json").read_text("utf-8"))["data"]
        self.pb = {m["name"]: m for m in pb}
        self.metals = {m["key"]: m for m in json.loads((folder / "metals_rgb.json").read_text("utf-8"))["metals"]}
        self.dielectrics = json.loads((folder / "dielectrics.json").read_text("utf-8"))

    def pb_values(self, row: str) -> dict[str, Any]:
        m = self.pb[row]
        colour = next(c["color"] for c in m["color"] if c["colorSpace"] == "srgb-linear")
        out = {"base_color": colour, "f0": colour, "ior": m.get("ior"), "roughness": m.get("roughness")}
        for c in m.get("complexIor") or []:
            if c["colorSpace"] == "srgb-linear":
                out |= {"eta": c["n"], "k": c["k"], "f82": [fresnel(n, k, MU_82) for n, k in zip(c["n"], c["k"])]}
        return out

    def dielectric_values(self, row: str) -> list[dict[str, Any]]:
        """Candidate value sets a dielectrics.json row name stands for (a class has several)."""
        d = self.dielectrics
        found = [{"ior": r["n_550nm"]} for r in d["refractive_indices"] if r["name"] == row]
        for r in d["classes"].get(row, []):
            found.append({"base_color": r.get("albedo_srgb_linear"), "ior": r.get("ior")})
        pb = d["physicallybased_all_dielectrics"].get(row)
        if pb:
            found.append({"base_color": pb["albedo_srgb_linear"], "ior": pb["ior"], "roughness": pb["roughness"]})
        return found

    def metal_values(self, key: str, dataset: str) -> dict[str, Any]:
        metal = self.metals[key]
        row = next(r for r in [metal["primary"], *metal["alternatives"]] if r["dataset"] == dataset)
        f82 = row.get("F82_srgb_linear") or [fresnel(n, k, MU_82) for n, k in zip(row["eta_rgb_fit"], row["k_rgb_fit"])]
        f0 = row["F0_srgb_linear"]
        if not all(0.0 <= v <= 1.0 for v in f0):  # Au's red (1.0376): the exact Fresnel of the fitted eta/k
            f0 = [round(fresnel(n, k, 1.0), 4) for n, k in zip(row["eta_rgb_fit"], row["k_rgb_fit"])]
        return {"eta": row["eta_rgb_fit"], "k": row["k_rgb_fit"], "f0": f0, "f82": f82}


@pytest.fixture(scope="module")
def data():
    if not (DATA / "physicallybased_materials.json").exists():
        pytest.skip("../shared/data is not beside this checkout")
    return Data(DATA)


def test_every_known_dataset_exists(data):
    for name in KNOWN_DATASETS:
        assert (DATA / name).is_file(), name


def test_verbatim_citations_match_the_dataset_row(stdlib, data):
    checked = 0
    for key, entry in nouns(stdlib).items():
        for file, row, fields in CITATION.findall(entry.get("source")):
            names = [f.strip() for f in fields.split(",")]
            if file == "physicallybased_materials.json":
                assert row in data.pb, (key, row)
                candidates = [data.pb_values(row)]
            else:
                assert file == "dielectrics.json", (key, file)
                candidates = data.dielectric_values(row)
                assert candidates, (key, row)
            assert any(all(close(entry.get(f), c.get(f)) for f in names) for c in candidates), (key, row, names)
            checked += 1
    assert checked >= 40


def test_metal_optics_match_metals_rgb(stdlib, data):
    checked = 0
    for key, entry in nouns(stdlib).items():
        for metal, dataset in METAL_CITATION.findall(entry.get("source")):
            values = data.metal_values(metal, dataset)
            for field in ("eta", "k", "f0", "f82"):
                assert close(entry.get(field), values[field]), (key, field, entry.get(field), values[field])
            checked += 1
    assert checked >= 30


def test_rows_named_in_prose_exist(stdlib, data):
    for key, entry in nouns(stdlib).items():
        for row in FREE_PB_ROW.findall(entry.get("source")):
            assert row in data.pb, (key, row)
