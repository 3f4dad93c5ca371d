"""The phrases whose tokens, AST and IR are kept as golden files (tests/language/golden/)."""

import json
from dataclasses import asdict
from pathlib import Path

from cnlmc.api import compile_source, lexicon_for
from cnlmc.document import iter_lines, parse_document
from cnlmc.tagger import Tagger

GOLDEN = Path(__file__).parent / "golden"

CASES = {
    "noun": "aluminum",
    "adjective_noun": "anodized aluminum",
    "colour_adjective_noun": "blue anodized aluminum",
    "groups": "lightly brushed, blue anodized aluminum",
    "and": "brushed and anodized aluminum",
    "or_variants": "hull: red or blue anodized aluminum",
    "coat_clause": "oak with a glossy white varnish",
    "multiword": "brushed stainless steel with a clear coat",
    "shades": "pale dark slate gray plastic",
    "refinements": "blue anodized aluminum\ndarker blue\nless diffuse\nmore diffuse",
    "maps": "heavily rusted iron",
    "diffuse": "weathered concrete",
    "glass": "frosted glass",
    "plated": "gold plated steel",
    "warnings": "polished rough steel\nanodized wood",
    "removal": "lightly brushed red anodized aluminum with fine scratches\ncan we lose the brushed look\ndeeper, a bit more of a burgundy",
}


def tokens_of(text: str, lexicon) -> list:
    tagger = Tagger(lexicon)
    out = []
    for number, offset, line in iter_lines(text):
        tagged, _ = tagger.tag_line(line, number, offset)
        out += [{"text": t.text, "span": t.span.as_list(), "tags": [c.tag for c in t.candidates]} for t in tagged]
    return out


def stages(text: str) -> dict:
    lexicon = lexicon_for()
    doc = parse_document(text, lexicon, "golden.cnl")
    ast = [{"node": type(i).__name__, **asdict(i)} for i in doc.items]
    ir = compile_source(text, "golden.cnl", lexicon).ir
    ir["lexicon"] = ["<stdlib>"]  # the install path differs between machines
    return {"tokens": tokens_of(text, lexicon), "ast": ast, "ir": ir}


def golden_path(name: str, stage: str) -> Path:
    return GOLDEN / f"{name}.{stage}.json"


def dump(value) -> str:
    return json.dumps(value, indent=1, ensure_ascii=False, sort_keys=True) + "\n"
