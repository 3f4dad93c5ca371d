"""The facade: parse, analyze, emit, compile. What the CLI, the LSP and pipelines call."""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property, lru_cache
from pathlib import Path
from typing import Any

from . import ast
from .analyze import analyze, iter_material_irs, sort_diagnostics, to_ir
from .cache import collection_paused
from .diagnostics import Diagnostic, has_errors, render_all
from .document import parse_document
from .ir import document_head, document_ir
from .lexicon import Lexicon, cached_lexicon
from .material import Document
from .state import Context, MaterialState
from .workers import worker_count

JSONDict = dict[str, Any]

#: the cyclic GC off while a document compiles: its many small containers live to the end and
#: make no cycles worth collecting (reference counting frees the rest)
cyclic_gc_paused = collection_paused


def lexicon_for(specs: Iterable[str | Path] = ()) -> Lexicon:
    """`specs` are overlay names ('paper') or lexicon folders; folders are searched first."""
    paths = tuple(str(s) for s in specs if Path(s).is_dir())
    overlays = tuple(str(s) for s in specs if not Path(s).is_dir())
    return cached_lexicon(paths, overlays)


@dataclass
class Result:
    """What compiling one source gives: the IR, diagnostics, and the stages on the way.

    `ir` is the JSON form; `document` the same as typed records (cnlmc.material.Document, made on
    first use); `source_document` the parsed source (the syntax tree)."""

    ir: JSONDict
    diagnostics: list[Diagnostic]
    source_document: ast.Document | None = None
    states: list[MaterialState] = field(default_factory=list)

    @cached_property
    def document(self) -> Document:
        """The IR as typed, validated records: what the backends receive."""
        with cyclic_gc_paused():
            return Document.from_ir(self.ir)

    @property
    def ok(self) -> bool:
        return not has_errors(self.diagnostics)

    @property
    def materials(self) -> list[JSONDict]:
        materials: list[JSONDict] = self.ir["materials"]
        return materials


def compile_source(
    source: str, filename: str = "<input>", lexicon: Lexicon | None = None, seed: int = 0, *, keep_stages: bool = True
) -> Result:
    """Parse, analyze and make the IR. `keep_stages=False` lets the syntax tree and the material
    states go once the IR is made (`source_document` None, `states` empty): the CLI needs only the
    IR, and on a large file those stages are most of the memory."""
    lexicon = lexicon or lexicon_for()
    with cyclic_gc_paused():
        if not keep_stages:
            stream = compile_stream(source, filename, lexicon, seed, workers=1)
            materials = list(stream.materials)
            diags = stream.sorted_diagnostics()
            return Result(document_ir(materials, diags, filename, lexicon.sources), diags)
        doc = parse_document(source, lexicon, filename)
        ctx = Context(lexicon, seed=seed, filename=filename)
        states, diags = analyze(doc, ctx)
        return Result(to_ir(states, diags, ctx), diags, doc, states)


@dataclass
class Stream:
    """A document compiled as its materials are asked for (compile_stream): `head` is the IR
    document's fields before its materials; `materials` makes each material's IR in turn (the
    lines are parsed as they are reached; nothing of a material is kept once its IR is handed
    out); `diagnostics` grows as they are found, complete once `materials` is exhausted."""

    head: JSONDict
    materials: Iterator[Mapping[str, Any]]
    diagnostics: list[Diagnostic]

    def sorted_diagnostics(self) -> list[Diagnostic]:
        """Every diagnostic by position (call once `materials` is exhausted)."""
        return sort_diagnostics(self.diagnostics)

    @property
    def ok(self) -> bool:
        return not has_errors(self.diagnostics)


def compile_stream(
    source: str, filename: str = "<input>", lexicon: Lexicon | None = None, seed: int = 0, workers: int | None = None
) -> Stream:
    """The document's IR one material at a time (see Stream): what `compile_source(keep_stages=False)`
    gives, without holding the materials. Iterate with the cyclic GC paused (cyclic_gc_paused).

    A large document is compiled by `workers` processes (None: $CNLMC_WORKERS, else the CPUs;
    see cnlmc.workers.worker_count), its materials then EncodedMaterial mappings, in the same
    order, with the same diagnostics and the same bytes once written."""
    lexicon = lexicon or lexicon_for()
    ctx = Context(lexicon, seed=seed, filename=filename)
    diags: list[Diagnostic] = []
    count = worker_count(source, workers)
    materials: Iterator[Mapping[str, Any]]
    if count == 1:
        materials = iter_material_irs(source, ctx, diags)
    else:
        from .parallel import parallel_material_irs  # multiprocessing only for a large document

        materials = parallel_material_irs(source, ctx, diags, count)
    return Stream(document_head(filename, lexicon.sources), materials, diags)


def compile_phrase(phrase: str, lexicon: Lexicon | None = None, seed: int = 0) -> JSONDict:
    """One phrase -> its first material's IR (raises ValueError with the rendered errors)."""
    result = compile_source(phrase, "<phrase>", lexicon, seed)
    if not result.ok or not result.materials:
        raise ValueError(
            "\n".join(render_all([d for d in result.diagnostics if d.is_error], phrase, "<phrase>"))
            or "the phrase names no material"
        )
    return result.materials[0]


def emit(ir: JSONDict | Document, target: str, options: dict[str, object] | None = None) -> Any:
    """Run a backend on an IR document (its JSON form or typed); returns its artifacts."""
    from cnlmc.backends.registry import get_target

    return get_target(target).emit_ir(ir, options or {})


def refined(
    document: str, words: str, lexicon: Lexicon, name: str, seed: int = 0, before: Result | None = None
) -> tuple[str, Result]:
    """The document with `words` added as a refinement line, and its compile result. Describing
    words alone start a material of their own (cnlmc.implied: 'purple' = purple paint), but said as
    a refinement they mean a change of the material there: they are added as the change line
    'make it purple' ('mach es lila' in German: teaching.toml [politeness] change_phrase). Anything
    else is added as it was said. `before`: the document's own result, when the caller has it."""
    from .suggest import teaching

    base = document.rstrip("\n")
    words = _complaint_as_change(words, teaching()["politeness"], lexicon)
    text = f"{base}\n{words}"
    trial = compile_source(text, name, lexicon, seed)
    known = before if before is not None else compile_source(base, name, lexicon, seed)
    if len(trial.materials) > len(known.materials):
        coated = f"{base}\nwith {words}"  # 'a glossy varnish': under a material, a coat said alone is added
        clause = compile_source(coated, name, lexicon, seed)
        if clause.ok and len(clause.materials) == len(known.materials):
            return coated, clause
        text = f"{base}\n{_change_phrase(lexicon, teaching()['politeness'])} {words}"
        trial = compile_source(text, name, lexicon, seed)
    return text, trial


def _change_phrase(lexicon: Lexicon, table: Mapping[str, Any]) -> str:
    """'make it', or the change phrase of the lexicon's language (an overlay folder named for it)."""
    phrases: Mapping[str, str] = table["change_phrase"]
    for source in lexicon.sources:
        language = Path(source).name
        if language in phrases:
            return phrases[language]
    return phrases["en"]


def _complaint_as_change(words: str, table: Mapping[str, Any], lexicon: Lexicon) -> str:
    """'too dark', "it's way too shiny": the change a complaint asks for ('less dark', 'much less
    shiny'); each part of a line of parts is read so ('more muted, it's a bit loud'); any other
    words as they are."""
    from .back import goes_back

    if goes_back(words):  # 'ooh too far, go back a little': going back, not a complaint (cnlmc.back)
        return words
    words = _comma_before_complaint(words, table["inner_complaint_openers"], table["inner_complaint_not_after"])
    if "," not in words:
        return _complaint_part(words, table, lexicon)
    parts = words.split(",")
    changed = [_complaint_part(part, table, lexicon) for part in parts]
    read = [_part_words(part, lexicon) for part in changed]
    describing = [_describing_only(words) for words in read]
    if any(_comparative(words) for words in read) and any(describing):  # 'lighter, almost white'
        phrase = _change_phrase(lexicon, table)
        changed = [f"{phrase} {part}" if alone else part for part, alone in zip(changed, describing)]
    if changed == parts:
        return words
    return ", ".join(" ".join(part.split()) for part in changed if part.strip())


def _comma_before_complaint(words: str, openers: Sequence[str], not_after: Sequence[str] = ()) -> str:
    """A change run on into its complaint without a comma ('lighter please its too dark'): the
    comma put before the complaint's opener (teaching.toml [politeness] inner_complaint_openers),
    so each part is read; not after a likeness ('like it's been waxed') nor at the line's start."""
    said = words.split()
    low = [w.lower() for w in said]
    for k in range(1, len(said)):
        if low[k] in openers and not said[k - 1].endswith(",") and low[k - 1] not in not_after:
            if "too" in low[k + 1 :]:  # a complaint, not a remark ('it's fine')
                return " ".join(said[:k]) + ", " + " ".join(said[k:])
    return words


def _describing_only(words: list[Any] | None) -> bool:
    """Whether a part of a change line (its words as tagged) is describing words alone ('almost
    white', 'almost polished'): said beside comparatives it is a change of the material, as 'make
    it almost white'."""
    from .joins import DESCRIBING

    return (
        bool(words)
        and all(c.tag in DESCRIBING for w in words or () for c in w.candidates)
        and any(c.tag != "ADV" for w in words or () for c in w.candidates)
    )


def _comparative(words: list[Any] | None) -> bool:
    """Whether a part of a change line (its words as tagged) has a comparative ('lighter', 'a bit
    darker')."""
    return any(c.tag == "REFINE" for w in words or () for c in w.candidates)


def _part_words(part: str, lexicon: Lexicon) -> list[Any] | None:
    """The part's words as the tagger reads them (marks left out), or None when it has an error."""
    from .tagger import Tagger

    tagged, problems = Tagger.of(lexicon).tag_line(part, 1, 0)
    if any(d.is_error for d in problems):
        return None
    return [w for w in tagged if w.text[:1].isalnum()]


def _complaint_part(words: str, table: Mapping[str, Any], lexicon: Lexicon) -> str:
    """One part of a line read as a complaint (see _complaint_as_change), or as it was."""
    said = " ".join(words.split())
    low = said.lower()
    named = _named_complaint(low, table, lexicon)
    if named is not None:
        return named
    opened = False
    openers = sorted(table["complaint_openers"], key=len, reverse=True)
    while True:  # "hmm, that's way too shiny": openers one after the other
        opener = next((o for o in openers if low.startswith(o + " ")), None)
        if opener is None:
            break
        said, low, opened = said[len(opener) + 1 :], low[len(opener) + 1 :], True
    complaints = dict(table["complaints"])
    if opened and not _comparative_next(low, table["opened_complaints"], lexicon):
        complaints.update(table["opened_complaints"])
    for complaint in sorted(complaints, key=len, reverse=True):
        if low.startswith(complaint + " "):
            return f"{complaints[complaint]} {said[len(complaint) + 1 :]}"
    return words


DESCRIBING_CATEGORIES = frozenset({"adjectives", "colours", "shades"})


@lru_cache(maxsize=1)
def _named_complaint_pattern() -> re.Pattern[str]:
    """'<lead> <feature> <verb> [degree] too <word>', from teaching.toml [politeness]."""
    leads, verbs = _complaint_leads_and_verbs()
    return re.compile(rf"^(?:{leads}) (?P<what>[a-z' -]+?) (?:{verbs}) (?P<degree>.*?)\s*too (?P<how>\S+)$")


def _complaint_leads_and_verbs() -> tuple[str, str]:
    """teaching.toml [politeness] named_complaint_leads and _verbs, each as a regex alternation."""
    from .suggest import teaching

    table = teaching()["politeness"]
    leads = "|".join(re.escape(w) for w in table["named_complaint_leads"])
    return leads, "|".join(re.escape(w) for w in table["named_complaint_verbs"])


@lru_cache(maxsize=1)
def _much_pattern() -> re.Pattern[str]:
    """'<lead> <what> <verb> <how much>' ('the red is a bit much'), from teaching.toml [politeness]."""
    from .suggest import teaching

    leads, verbs = _complaint_leads_and_verbs()
    table = teaching()["politeness"]
    much = "|".join(re.escape(w) for w in sorted(table["named_complaint_much"], key=len, reverse=True))
    return re.compile(rf"^(?:{leads}) (?P<what>[a-z' -]+?) (?:{verbs}) (?P<much>{much})$")


def _named_complaint(low: str, table: Mapping[str, Any], lexicon: Lexicon) -> str | None:
    """'the brushing is too strong', 'the veining is a bit too busy': a complaint about a feature or
    property the line names is less of it ('less brushing', 'a bit less veining'); so is one that
    only says how much is too much, of a colour too ('the red is a bit much' = a bit less red);
    None for any other part (what is too much about it — strong, busy, loud — only says that it
    is too much)."""
    much = _much_pattern().match(low)
    if much is not None:
        named = {e.category for e in lexicon.lookup(tuple(much["what"].split()))}
        if named & {"properties", "features", "colours"}:
            return f"{table['named_complaint_much'][much['much']]} {much['what']}"
    found = _named_complaint_pattern().match(low)
    if found is None:
        return None
    what = found["what"]
    if not any(e.category in ("properties", "features") for e in lexicon.lookup(tuple(what.split()))):
        return None
    if any(e.category in DESCRIBING_CATEGORIES for e in lexicon.lookup((found["how"],))):
        return None  # 'the colour is too dark': less dark (the openers' reading), not less colour
    complaint = f"{found['degree']} too".strip()
    reading = table["complaints"].get(complaint)
    return None if reading is None else f"{reading} {what}"


def _comparative_next(low: str, degrees: Mapping[str, str], lexicon: Lexicon) -> bool:
    """ "it's a bit darker now": the word after the degree is a comparative, a refinement word of
    the lexicon (a report, no complaint; "it's a bit amber" is a colour)."""
    for degree in sorted(degrees, key=len, reverse=True):
        if low.startswith(degree + " "):
            rest = low[len(degree) + 1 :].split()
            return bool(rest) and any(e.category == "refinements" for e in lexicon.lookup((rest[0],)))
    return False


class Session:
    """Interactive refinement: session.refine("darker") changes the material, as in the paper."""

    def __init__(self, phrase: str, lexicon: Lexicon | None = None, seed: int = 0, filename: str = "<session>") -> None:
        self.lines = [phrase]
        self.lexicon = lexicon or lexicon_for()
        self.seed = seed
        self.filename = filename
        self.result = self._compile()

    def _compile(self) -> Result:
        return compile_source(self.text(), self.filename, self.lexicon, self.seed)

    def text(self, extra: Iterable[str] = ()) -> str:
        """The source compiled: the phrase and every refinement line (plus `extra` lines)."""
        return "\n".join([*self.lines, *extra])

    def trial(self, words: str) -> Result:
        """What adding the refinement line would compile to; the session is left as it is."""
        return self._refined(words)[1]

    def refine(self, words: str) -> JSONDict:
        """Apply a refinement line; a line that fails leaves the material as it was. Describing
        words alone change the material ('matte', 'too dark': `refined`), as every line said in a
        session refines it."""
        line, result = self._refined(words)
        if not result.ok:
            raise ValueError("; ".join(d.message for d in result.diagnostics if d.is_error))
        self.lines.append(line)
        self.result = result
        return self.material

    def _refined(self, words: str) -> tuple[str, Result]:
        text, result = refined(self.text(), words, self.lexicon, self.filename, self.seed, self.result)
        return text.rsplit("\n", 1)[-1], result

    def undo(self) -> JSONDict:
        """Drop the last refinement line (ValueError when there is none); returns the material."""
        if len(self.lines) < 2:
            raise ValueError("nothing to undo")
        self.lines.pop()
        self.result = self._compile()
        return self.material

    @property
    def material(self) -> JSONDict:
        return self.result.materials[0]

    @property
    def warnings(self) -> list[Diagnostic]:
        return [d for d in self.result.diagnostics if not d.is_error]


def build(catalog: str | Path, out: str | Path, targets: Iterable[str], **settings: Any) -> JSONDict:
    """Build every material of a catalogue (a .cnl file or a folder of them) to every target into
    `out`, incrementally and in parallel; returns the manifest (also written to
    OUT/cnlmc-build.json). Settings: size, jobs, scheduler, results, options, lexicon, seed
    (cnlmc.batch.build_report, docs/build.md)."""
    from .batch import build as build_catalog  # the batch front end, only when a build is asked for

    return build_catalog(catalog, out, list(targets), **settings)
