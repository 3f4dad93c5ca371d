"""The canonical order describing groups apply in, whatever the order of the words (issue #14).

Adjectives apply by their `stage` (stdlib/schema.toml; docs/language.md "Degrees and order"):
shaping (brushed, sandblasted), treatment (anodized, oiled, painted), finish (matte, polished),
then the colour words, then ageing (rusty, weathered), then coats (varnished). Within a stage an
adjective that sets a value applies before one that scales or shifts it ("satin shiny" = shiny
satin), the rest by key, so word order never changes the numbers, except where two words of one
stage contradict each other (or two colours meet): then that stage keeps the phrase order, and the
later word applies last and wins.
"""

from __future__ import annotations

from collections.abc import Sequence

from .. import ast
from ..lexicon import Entry, Lexicon, LexiconCaches
from ..lexicon_model import normalise

STAGES = ("shaping", "treatment", "finish", "colour", "ageing", "coat")
DEFAULT_STAGE = "finish"  # an adjective without a declared stage describes the surface's look
ATTACHED_COLOURS = ("coat", "material")  # colour targets that keep the colour with its adjective


def stage_of(adjective: Entry) -> str:
    return str(adjective.get("stage", DEFAULT_STAGE))


GroupKey = tuple[str, "str | None", bool]  # (kind, adjective key or None, has a colour)
Step = tuple[int, str]  # (index of the group in the phrase, "all" | "colour" | "adjective" part of it)


def canonical_groups(groups: Sequence[ast.Group], lexicon: Lexicon) -> Sequence[ast.Group]:
    groups = _colour_to_its_coat(_shade_words_as_adjectives(groups, lexicon), lexicon)
    if len(groups) < 2 and not (groups and groups[0].colours and groups[0].adjectives):
        return groups
    key = tuple([(g.kind, g.adjectives[0].key if g.adjectives else None, bool(g.colours)) for g in groups])
    memo = lexicon.caches.stage_orders
    plan = memo.get(key)
    if plan is None:
        if len(memo) >= LexiconCaches.MAX_ENTRIES:
            memo.clear()
        plan = memo[key] = _plan(groups, lexicon)
    if not plan:
        return groups  # already in canonical order
    return [_part(groups[index], part) for index, part in plan]


def _colour_to_its_coat(groups: Sequence[ast.Group], lexicon: Lexicon) -> Sequence[ast.Group]:
    """'white glossy lacquered MDF' = 'glossy white lacquered MDF': the phrase's one colour, said
    before a word that leaves colours on the base ('glossy'), goes with the phrase's one word that
    takes its colour to a coat ('lacquered', colour_target "coat") when that word has none of its
    own, wherever it stands; the groups as they were otherwise."""
    coloured = [i for i, g in enumerate(groups) if g.colours]
    takers = [i for i, g in enumerate(groups) if not g.colours and _takes_coat_colour(g, lexicon)]
    if len(coloured) != 1 or len(takers) != 1:
        return groups
    giver, taker = groups[coloured[0]], groups[takers[0]]
    adjective = _adjective(giver, lexicon)
    if giver.adverbs or len(giver.colours) != 1 or adjective is None or adjective.get("colour_target"):
        return groups
    moved = list(groups)
    moved[coloured[0]] = ast.Group(giver.kind, (), (), giver.adjectives, giver.span)
    moved[takers[0]] = ast.Group(taker.kind, taker.adverbs, giver.colours, taker.adjectives, taker.span)
    return moved


def _takes_coat_colour(group: ast.Group, lexicon: Lexicon) -> bool:
    adjective = _adjective(group, lexicon)
    return adjective is not None and adjective.get("colour_target") == "coat"


def _plan(groups: Sequence[ast.Group], lexicon: Lexicon) -> tuple[Step, ...]:
    """The order of the groups (and of their colour and adjective parts); () when it is the phrase's."""
    stages: dict[int, list[tuple[Step, ast.Group]]] = {}
    for step, group in _colours_apart(groups, lexicon):
        stages.setdefault(_rank(group, lexicon), []).append((step, group))
    plan = _rejoin([step for rank in sorted(stages) for step in _within_stage(stages[rank], lexicon)])
    identity = tuple((i, "all") for i in range(len(groups)))
    return () if plan == identity else plan


def gloss_on_coat(groups: Sequence[ast.Group], lexicon: Lexicon, coated: bool) -> tuple[ast.Group, ...]:
    """The finish words that only set how glossy the surface is ("matte", "polished"), when the
    material has a coat (its noun's, or a word of the phrase that lays one): they describe the coat,
    which is what one sees, so they apply to it after it is laid ("matte varnished oak" is a matte
    varnish, "glossy powder-coated steel" a glossy powder coat)."""
    if not groups:
        return ()
    facts = [_coat_facts(g, lexicon) for g in groups]
    if not coated and (True, False) not in facts and (True, True) not in facts:  # no group lays a coat
        return ()
    return tuple([g for g, (_lays, gloss) in zip(groups, facts, strict=True) if gloss])


_NO_ADJECTIVE = (False, False)


def _coat_facts(group: ast.Group, lexicon: Lexicon) -> tuple[bool, bool]:
    """(_lays_coat, a finish word that only sets the gloss) of a group: read once per lexicon
    adjective (LexiconCaches.coat_facts), not on every phrase (#13, #14 speed)."""
    adjective = _adjective(group, lexicon)
    if adjective is None:
        return _NO_ADJECTIVE
    memo = lexicon.caches.coat_facts
    found = memo.get(adjective.key)
    if found is None or found[0] is not adjective:
        if len(memo) >= LexiconCaches.MAX_ENTRIES:
            memo.clear()
        gloss = stage_of(adjective) == "finish" and _gloss_only(adjective)
        found = memo[adjective.key] = (adjective, _lays_coat(group, lexicon), gloss)
    return found[1], found[2]


def _lays_coat(group: ast.Group, lexicon: Lexicon) -> bool:
    """A coat word ('varnished'), or a treatment that lays a layer on top ('powder-coated')."""
    adjective = _adjective(group, lexicon)
    if adjective is None or (adjective.get("coat") and _conformal(adjective.get("coat"), lexicon)):
        return False  # a conformal film (an anodic oxide) has the base's surface: gloss stays on the base
    return stage_of(adjective) == "coat" or bool(adjective.get("coat"))


def _conformal(coat: str, lexicon: Lexicon) -> bool:
    entry = lexicon.entry("coats", coat)
    return entry is not None and bool(entry.get("follows_base"))


def _gloss_only(adjective: Entry | None) -> bool:
    if adjective is None or adjective.get("maps") or adjective.get("material") or adjective.get("coat"):
        return False
    effects = adjective.get("effects", [])
    per_class = [e for formulas in adjective.get("on", {}).values() for e in formulas]
    return bool(effects) and all(e.get("param") == "roughness" for e in (*effects, *per_class))


def _shade_words_as_adjectives(groups: Sequence[ast.Group], lexicon: Lexicon) -> Sequence[ast.Group]:
    """A shade with no colour after it that is also an adjective ("dusty glass", "dusty dull brass",
    unlike "dusty pink") is the adjective: dust on the glass, not a muted colour."""
    out: list[ast.Group] | None = None
    for index, group in enumerate(groups):
        adjective = _shade_adjective(group, lexicon)
        if adjective is None:
            if out is not None:
                out.append(group)
            continue
        out = list(groups[:index]) if out is None else out
        out += _as_adjective(group, adjective)
    return groups if out is None else out


def _as_adjective(group: ast.Group, adjective: ast.Word) -> list[ast.Group]:
    colour = group.colours[0]
    out = []
    if len(colour.shades) > 1:  # "dark dusty glass": the other shades stay a colour
        rest = ast.Colour(colour.shades[:-1], None, colour.span)
        out.append(ast.Group("colour", (), (rest,), (), group.span))
    out.append(ast.Group("adjective", group.adverbs, (), (adjective,), group.span))
    if group.adjectives:  # "dusty dull": the adjective that followed keeps its place
        out.append(ast.Group(group.kind, (), (), group.adjectives, group.span))
    return out


def _shade_adjective(group: ast.Group, lexicon: Lexicon) -> ast.Word | None:
    if len(group.colours) != 1 or group.kind not in ("colour", "adjective"):
        return None
    colour = group.colours[0]
    if colour.base is not None or not colour.shades or colour.noun is not None:
        return None
    word = colour.shades[-1]
    for entry in lexicon.lookup(normalise(word.text)):
        if entry.category == "adjectives":
            return ast.Word(word.text, entry.key, "adjectives", word.span)
    return None


def _rejoin(steps: list[Step]) -> tuple[Step, ...]:
    """An adjective whose own colour applies right after it is the group as written ("dark oiled")."""
    out: list[Step] = []
    for step in steps:
        if step[1] == "colour" and out and out[-1] == (step[0], "adjective"):
            out[-1] = (step[0], "all")
        else:
            out.append(step)
    return tuple(out)


def _part(group: ast.Group, part: str) -> ast.Group:
    if part == "colour":  # the adverbs stand before the colour and modify it ("very dark")
        return ast.Group("colour", group.adverbs, group.colours, (), group.span)
    if part == "adjective":
        return ast.Group(group.kind, (), (), group.adjectives, group.span)
    return group


def _colours_apart(groups: Sequence[ast.Group], lexicon: Lexicon) -> list[tuple[Step, ast.Group]]:
    """A colour before an adjective that puts it on the base ("green faded", "blue anodized") is a
    colour word of its own, applied in the colour stage; one that goes to a coat or names a plating
    metal ("white varnished", "gold plated") stays with its adjective."""
    out: list[tuple[Step, ast.Group]] = []
    for index, group in enumerate(groups):
        adjective = _adjective(group, lexicon)
        if adjective is None or not group.colours or adjective.get("colour_target") in ATTACHED_COLOURS:
            out.append(((index, "all"), group))
            continue
        for part in ("colour", "adjective"):
            out.append(((index, part), _part(group, part)))
    return out


def _rank(group: ast.Group, lexicon: Lexicon) -> int:
    """The stage a group applies in (colour words have their own; unknown words come last)."""
    if group.kind == "colour":
        return STAGES.index("colour")
    adjective = _adjective(group, lexicon)
    if adjective is None:
        return len(STAGES)  # dangling adverbs and unknown words: last, in phrase order
    return STAGES.index(stage_of(adjective))


def _adjective(group: ast.Group, lexicon: Lexicon) -> Entry | None:
    if group.kind != "adjective" or not group.adjectives or group.adjectives[0].unknown:
        return None
    return lexicon.entry("adjectives", group.adjectives[0].key)


def _sets_a_value(adjective: Entry) -> bool:
    effects = adjective.get("effects", [])
    return bool(adjective.get("material")) or any(e.get("op") == "set" for e in effects)


def _within_stage(members: list[tuple[Step, ast.Group]], lexicon: Lexicon) -> list[Step]:
    """Phrase order where two members contradict each other (or are colours); else the words that
    set a value first, then those that scale or shift one, each by adjective key."""
    entries = [_adjective(g, lexicon) for _, g in members]
    known = [e for e in entries if e is not None]
    if len(members) < 2 or len(known) < len(entries) or _any_opposed(known):
        return [step for step, _ in members]
    keyed = sorted(zip(known, members), key=lambda pair: (not _sets_a_value(pair[0]), pair[0].key, pair[1][0]))
    return [member[0] for _, member in keyed]


def _any_opposed(entries: list[Entry]) -> bool:
    keys = {e.key for e in entries}
    return any(keys & set(e.get("opposes", [])) for e in entries)
