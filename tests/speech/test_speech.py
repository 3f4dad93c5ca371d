"""Speech input (issue #18): the grammar generated from the lexicon, `cnlmc listen`, and the
speech test set spoken by espeak-ng (4 voices, 3 speeds, clean and 20 dB SNR), scored on the IR
the recognised phrases compile to. Skips only when pocketsphinx, espeak-ng or sox is absent."""

from __future__ import annotations

import json
import subprocess
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np
import pytest

from cnlmc.api import compile_source, lexicon_for
from tests.helpers import run_cnlmc

pytest.importorskip("pocketsphinx", reason="speech input needs pocketsphinx (pip install 'cnlmc[speech]')")

from cnlmc.speech.grammar import Grammar
from cnlmc.speech.model import SpeechModel
from cnlmc.speech.recogniser import Recogniser
from cnlmc.speech.testset import (
    IR_FIELDS,
    SPEEDS,
    VOICES,
    Phrases,
    Scorer,
    Utterance,
    read_pcm,
    synthesize,
    tools_missing,
)

ROOT = Path(__file__).resolve().parents[2]
needs_tools = pytest.mark.skipif(bool(tools_missing()), reason=f"the test set needs {' and '.join(tools_missing())}")

# Floors: what this package measured (bench/speech.py --quick), so a regression fails. The issue's
# goals (95 % / 85 %) are printed by the bench; see docs/speech.md for where they stand.
CLEAN_FLOOR = 0.45  # measured 55.0-62.5 % of 120 (session 16; 46.7-48.3 % in session 9, 30.8-37.5 % in session 8)
NOISY_FLOOR = 0.40  # measured 65 % of 20 (session 16; the noise is drawn afresh each run; 45-60 % in session 9)


@pytest.fixture(scope="module")
def model() -> SpeechModel:
    return SpeechModel.of(lexicon_for())


@pytest.fixture(scope="module")
def recogniser(model: SpeechModel) -> Recogniser:
    return model.recogniser()


@pytest.fixture(scope="module")
def audio_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("speech")


def materials_of(ir: dict) -> list[dict]:
    return [{k: m.get(k) for k in IR_FIELDS} for m in ir["materials"]]


# ---------------------------------------------------------------- the grammar


def test_grammar_accepts_only_complete_phrases(model: SpeechModel, recogniser: Recogniser) -> None:
    accept = recogniser.fsg.accept
    for phrase in (
        "lightly brushed blue anodized aluminum",
        "white varnished oak",
        "darker",
        "more glossy",
        "less grain",
        "undo",
        "polished copper with a clear coat",
        "blue anodised aluminium",
        "purple",  # describing words alone: a change later, their implied material first
        "matte black",
    ):
        assert accept(phrase), phrase
    for partial in ("lightly", "very lightly", "polished copper with a", "with", "and", "white varnished oak and"):
        assert not accept(partial), partial


def test_every_grammar_word_has_a_pronunciation(model: SpeechModel) -> None:
    pronounced = {line.split()[0].split("(")[0] for line in model.dictionary.splitlines()}
    assert model.grammar.words_used() <= pronounced
    assert not model.unsayable  # the bundled lexicon: every word (scripts/gen_pronunciations.py)
    assert "anodized" in pronounced and "aluminium" in pronounced and "aluminum" in pronounced


def test_a_user_lexicon_regenerates_the_grammar(tmp_path: Path) -> None:
    (tmp_path / "nouns_studio.toml").write_text(
        '[zorbium]\nclass = "plastic"\nmodel = "dielectric"\nroughness = 0.2\nbase_color = [0.9, 0.8, 0.7]\nior = 1.5\n'
        'source = "studio"\ndoc = "A studio metal."\nexample = "polished zorbium"\n',
        "utf-8",
    )
    lexicon = lexicon_for([str(tmp_path)])
    without = SpeechModel.of(lexicon, [tmp_path])
    (tmp_path / "speech").mkdir()
    (tmp_path / "speech" / "pronunciations.toml").write_text('[words]\nzorbium = ["Z AO R B IY AH M"]\n', "utf-8")
    with_file = SpeechModel.of(lexicon, [tmp_path])
    assert "zorbium" in with_file.grammar.words_used()
    assert "zorbium Z AO R B IY AH M" in with_file.dictionary.splitlines()
    # without the file the word is pronounced by espeak-ng when it is here, else named as unsayable
    assert ("zorbium" in without.grammar.words_used()) != ("zorbium" in without.unsayable)


# ---------------------------------------------------------------- the test set


@needs_tools
def test_the_speech_set_compiles_to_the_said_materials(
    model: SpeechModel, recogniser: Recogniser, audio_folder: Path
) -> None:
    phrases = Phrases.bundled(full=False)
    clean = phrases.utterances(VOICES, SPEEDS, (False,))
    noisy = phrases.utterances(VOICES[:2], (160,), (True,))
    assert len(clean) >= 120 and len({u.voice for u in clean}) >= 4
    scorer = Scorer(lexicon_for(), phrases, model.settings.undo)
    scores: dict[bool, list[bool]] = defaultdict(list)
    for utterance in clean + noisy:
        pcm = read_pcm(synthesize(utterance, audio_folder, model.settings.sample_rate))
        heard = recogniser.decode(pcm, refining=utterance.refinement)
        if heard is not None:  # whatever is heard is a complete phrase of the language
            assert recogniser.fsg.accept(heard.text)
        scores[utterance.noisy].append(scorer.ir_equal(utterance, heard.text if heard else None))
    clean_rate, noisy_rate = (sum(scores[n]) / len(scores[n]) for n in (False, True))
    print(
        f"IR-equal: clean {clean_rate:.1%} of {len(scores[False])}, 20 dB SNR {noisy_rate:.1%} of {len(scores[True])}"
    )
    assert clean_rate >= CLEAN_FLOOR and noisy_rate >= NOISY_FLOOR


# ---------------------------------------------------------------- cnlmc listen


def session_wav(folder: Path, said: list[str], rate: int) -> Path:
    """One recording of the utterances (en-us, 160 wpm), a second of silence after each."""
    parts = [synthesize(Utterance(text, "en-us", 160, False, False), folder, rate) for text in said]
    silence = folder / "silence.wav"
    subprocess.run(["sox", "-n", "-r", str(rate), "-c", "1", "-b", "16", str(silence), "trim", "0", "1"], check=True)
    out = folder / ("session_" + "_".join(t.replace(" ", "-") for t in said) + ".wav")
    subprocess.run(["sox", *(str(p) for part in parts for p in (part, silence)), str(out)], check=True)
    return out


@needs_tools
def test_listen_compiles_a_spoken_session_as_typed_text(model: SpeechModel, audio_folder: Path) -> None:
    said = ["white varnished oak", "darker", "darker", "undo"]
    wav = session_wav(audio_folder, said, model.settings.sample_rate)
    # every utterance is applied whatever its confidence: this checks the session, not the threshold
    done = run_cnlmc("listen", "--from", str(wav), "--min-confidence", "0")
    assert done.returncode == 0, done.stderr
    typed = compile_source("white varnished oak\ndarker", "typed.cnl", lexicon_for())
    assert materials_of(json.loads(done.stdout)) == materials_of(typed.ir)
    assert "heard 'undo'" in done.stderr and "dropped 'darker'" in done.stderr


@needs_tools
def test_below_the_threshold_nothing_is_applied(model: SpeechModel, audio_folder: Path) -> None:
    wav = session_wav(audio_folder, ["white varnished oak"], model.settings.sample_rate)
    done = run_cnlmc("listen", "--from", str(wav), "--min-confidence", "1.01")
    assert done.returncode == 1 and done.stdout == ""
    assert "heard 'white varnished oak'" in done.stderr and "not applied, below 1.01; alternatives:" in done.stderr


def test_listen_without_a_microphone_says_so() -> None:
    done = run_cnlmc("listen")
    assert done.returncode == 2
    assert "no audio input device" in done.stderr or "PortAudio" in done.stderr
    assert "Traceback" not in done.stderr


def test_listen_refuses_a_file_that_is_not_a_wav(tmp_path: Path) -> None:
    text = tmp_path / "notes.wav"
    text.write_text("white varnished oak\n", "utf-8")
    done = run_cnlmc("listen", "--from", str(text))
    assert done.returncode == 2 and "not a PCM WAV file" in done.stderr and "Traceback" not in done.stderr


def test_common_words_weigh_more_in_their_slot(model: SpeechModel) -> None:
    """A slot's words are weighted by the language model's word frequencies: 'steel' over 'terrazzo'."""
    by_source: dict[int, dict[str, float]] = defaultdict(dict)
    for transition in model.grammar.transitions:
        if len(transition) == 4:
            by_source[transition[0]][transition[3]] = transition[2]
    nouns = [arcs for arcs in by_source.values() if {"steel", "terrazzo"} <= set(arcs)]
    assert nouns
    for arcs in nouns:
        assert arcs["steel"] > 10 * arcs["terrazzo"]
        assert sum(arcs.values()) <= 1.0 + 1e-6  # the slot's shares of one


def test_british_pronunciations_beside_american_ones(model: SpeechModel) -> None:
    lines = set(model.dictionary.splitlines())
    assert {"darker D AA R K ER", "darker(2) D AA K AH"} <= lines


def test_a_noise_floor_fills_digital_silence_and_leaves_a_noisy_recording_alone() -> None:
    """Digital silence (a synthesiser's exact zeros) gets noise about `below_speech_db` under the
    speech; audio that already has a floor (white noise at 20 dB SNR) comes back as it was."""
    from cnlmc.speech.settings import SpeechSettings

    floor, rate = SpeechSettings.bundled().noise_floor, 16000
    time = np.arange(rate) / rate
    tone = np.where(time < 0.5, 4000.0 * np.sin(2 * np.pi * 220 * time), 0.0)  # half speech, half zeros
    silent = np.round(tone).astype("<i2").tobytes()
    filled = np.frombuffer(floor.apply(silent, rate), dtype="<i2").astype(np.float64)
    pause = filled[int(0.6 * rate) :]
    level = 20 * np.log10(4000 / np.sqrt(2) / np.sqrt(np.mean(pause**2)))
    assert abs(level - floor.below_speech_db) < 3, level
    noisy = np.round(tone + np.random.default_rng(0).normal(0, 4000 / np.sqrt(2) / 10, rate)).astype("<i2").tobytes()
    assert floor.apply(noisy, rate) == noisy


def test_the_floor_is_pink_noise_of_unit_level() -> None:
    """The floor's power falls as 1/f (slope 1): every octave holds about the same power, where
    white noise (slope 0) holds twice as much in each octave as in the one below it."""
    from cnlmc.speech.noise_floor import coloured_noise

    rate = 16000

    def octaves(slope: float) -> list[float]:
        noise = coloured_noise(rate * 4, rate, slope, np.random.default_rng(1))
        assert abs(np.sqrt(np.mean(noise**2)) - 1.0) < 0.02  # shaped noise exactly, white noise as drawn
        power = np.abs(np.fft.rfft(noise)) ** 2
        frequencies = np.fft.rfftfreq(noise.size, 1 / rate)
        return [float(power[(frequencies >= f) & (frequencies < 2 * f)].sum()) for f in (250, 500, 1000, 2000, 4000)]

    pink, white = octaves(1.0), octaves(0.0)
    assert max(pink) / min(pink) < 1.3, pink
    assert all(1.7 < high / low < 2.3 for low, high in zip(white, white[1:])), white
    assert np.all(np.isfinite(coloured_noise(3, rate, 1.0, np.random.default_rng(0))))  # too short to shape


def test_what_people_rarely_say_weighs_less(model: SpeechModel) -> None:
    """Each branching state's ways share a probability of 1 in proportion to how often people
    took them (stdlib/speech/branches.toml): 'and' between groups and 'or' between nouns, which
    nobody typed, weigh far less than going on without them; the words of a slot keep their order."""
    from cnlmc.speech.branches import branching

    grammar = model.grammar
    out: dict[int, float] = defaultdict(float)
    for transition in grammar.transitions:
        out[transition[0]] += transition[2]
    for state, slots in branching(grammar).items():
        if len(slots) > 1:
            assert abs(out[state] - 1.0) < 1e-6, (state, slots)
    by_slot: dict[str, list[float]] = defaultdict(list)
    for transition, slot in zip(grammar.transitions, grammar.slots, strict=True):
        by_slot[slot].append(transition[2])
    for joiner, usual in (
        ("material.group0.and", "material.group0.and.skip"),
        ("material.noun.or", "material.noun.end"),
        ("item0.comparative.and", "item0.comparative.end"),
    ):
        assert max(by_slot[joiner]) < 0.1 * min(by_slot[usual]), joiner


def test_branch_counts_follow_the_readings_of_a_phrase() -> None:
    """A toy grammar: [adverb] (colour | noun); a phrase with two readings counts each by half;
    weights are the add-one smoothed shares; the committed counts are current."""
    from cnlmc.speech.branches import count_branches, weigh_branches
    from cnlmc.speech.grammar import Grammar

    grammar = Grammar()
    middle = grammar.state()
    grammar.words(grammar.start, middle, ["very"], slot="adverb")
    grammar.skip(grammar.start, middle, "adverb.skip")
    grammar.words(middle, grammar.final, ["red", "rust"], slot="colour")
    grammar.words(middle, grammar.final, ["rust", "steel"], slot="noun")
    counts, said = count_branches(grammar, ["very red", "rust", "steel", "wood"])
    assert said == 3 and counts == {"adverb": 1, "adverb.skip": 2, "colour": 1.5, "noun": 1.5}
    weighted = weigh_branches(grammar, counts, 1.0)
    probability = {(t[3] if len(t) == 4 else "-", s): t[2] for t, s in zip(weighted.transitions, weighted.slots)}
    assert probability["very", "adverb"] == pytest.approx(2 / 5) and probability["-", "adverb.skip"] == pytest.approx(
        3 / 5
    )
    assert probability["red", "colour"] == pytest.approx(0.5 * 2.5 / 5)
    assert weigh_branches(grammar, {}, 0.0).transitions == grammar.transitions  # nothing counted, nothing changed
    check = subprocess.run(
        [sys.executable, "scripts/gen_speech_branches.py", "--check"], capture_output=True, text=True, cwd=ROOT
    )
    assert check.returncode == 0, check.stderr


def test_colours_written_joined_are_said_as_two_words(model: SpeechModel) -> None:
    """'darkgreen' (CSS) sounds as 'dark green', which the grammar says as a shade on a colour;
    English compounds stay sayable."""
    words = model.grammar.words_used()
    assert not {"darkgreen", "lightblue", "bluegrey"} & words
    assert {"dark", "green", "aquamarine", "strawberry"} <= words


def test_after_a_material_changes_are_likelier_than_new_materials(model: SpeechModel) -> None:
    """Two grammars of one structure: the first utterance of a session starts a material, later
    ones mostly change it, so the start's branches are weighed apart (stdlib/speech/branches.toml)."""

    def start(grammar: Grammar) -> dict[str, float]:
        found: dict[str, float] = defaultdict(float)
        for transition, slot in zip(grammar.transitions, grammar.slots, strict=True):
            if transition[0] == grammar.start:
                found[slot] += transition[2]
        return found

    first, later = start(model.grammar), start(model.later)
    assert first["start.material"] > 0.9 and later["start.refinement"] > 0.8
    assert first["start.describing"] > first["start.refinement"]  # 'matte black' starts paint; 'darker' nothing
    assert 0 < later["start.undo"] and 0 < first["start.refinement"]  # never impossible
    assert [t[:2] for t in model.grammar.transitions] == [t[:2] for t in model.later.transitions]


def test_spellings_of_one_sound_weigh_as_all_of_them(model: SpeechModel) -> None:
    """'grey' and 'gray' sound alike: each arc weighs as the two together (cnlmc.speech.homophones),
    so neither loses to 'grape' on the strength of a split share; a word of its own sound keeps its own."""
    by_source: dict[int, dict[str, float]] = defaultdict(dict)
    for transition in model.grammar.transitions:
        if len(transition) == 4:
            by_source[transition[0]][transition[3]] = transition[2]
    colours = [arcs for arcs in by_source.values() if {"grey", "gray", "grape"} <= set(arcs)]
    assert colours
    for arcs in colours:
        assert arcs["grey"] == pytest.approx(arcs["gray"])
        assert sum(arcs.values()) <= 1.0 + 1e-6


def test_pooling_sums_the_spellings_probabilities() -> None:
    import math

    from cnlmc.speech.homophones import with_homophones_pooled
    from cnlmc.speech.prior import WordPrior
    from cnlmc.speech.vocabulary import Vocabulary

    prior = WordPrior({"grey": math.log(0.01), "gray": math.log(0.03), "grape": math.log(0.02)}, math.log(1e-7), 0.5)
    table = {"grey": ["G R EY"], "gray": ["G R EY"], "grape": ["G R EY P"]}
    pooled = with_homophones_pooled(Vocabulary({"colours": ("grape", "gray", "grey")}), table, prior)
    assert pooled is not None
    assert pooled.of("grey") == pytest.approx(0.5 * math.log(0.04)) == pytest.approx(pooled.of("gray"))
    assert pooled.of("grape") == prior.of("grape")
    assert with_homophones_pooled(Vocabulary({"colours": ("grey",)}), table, None) is None
