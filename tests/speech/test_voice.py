"""Enrolment (issue #18): the recogniser adapted to a speaker from sentences read aloud (MLLR, then
MAP, on the acoustic model's means), the voice file, and `cnlmc listen --enrol / --voice`. The
model files are read with numpy and written back for pocketsphinx, the real consumer."""

from __future__ import annotations

import subprocess
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cnlmc.api import lexicon_for
from tests.helpers import run_cnlmc

pytest.importorskip("pocketsphinx", reason="speech input needs pocketsphinx (pip install 'cnlmc[speech]')")

from cnlmc.speech.enrol import Aligner, Script, enrol_recording
from cnlmc.speech.model import SpeechModel
from cnlmc.speech.pronounce import read_dictionary
from cnlmc.speech.recogniser import model_files
from cnlmc.speech.sphinx_files import gaussians_bytes, read_gaussians, read_log_weights
from cnlmc.speech.testset import Phrases, Scorer, Utterance, read_aloud, read_pcm, synthesize, tools_missing
from cnlmc.speech.voice import (
    AcousticModel,
    Statistics,
    Voice,
    VoiceError,
    acoustic_model,
    features,
    map_means,
    mllr,
    transformed,
)

needs_tools = pytest.mark.skipif(bool(tools_missing()), reason=f"the test set needs {' and '.join(tools_missing())}")
RATE = 16000
SPOKEN_PHONES = 39  # the model's phones less silence and the two noise phones


@pytest.fixture(scope="module")
def acoustic() -> AcousticModel:
    return acoustic_model(model_files().acoustic)


@pytest.fixture(scope="module")
def speech() -> SpeechModel:
    return SpeechModel.of(lexicon_for())


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("voice")


# ---------------------------------------------------------------- the model files


def test_the_bundled_model_reads_as_one_codebook_per_phone(acoustic: AcousticModel) -> None:
    assert acoustic.means.shape == (len(acoustic.ciphones), 3, 128, 13)
    assert {"SIL", "AA", "ZH"} <= set(acoustic.ciphones) and acoustic.ciphones == tuple(sorted(acoustic.ciphones))
    assert np.all(acoustic.variances > 0) and np.all(np.isfinite(acoustic.means))
    # each senone's weights over a codebook are a distribution (8-bit quantised: within a few %)
    totals = np.exp(acoustic.log_weights).sum(axis=1)
    assert np.all((totals > 0.85) & (totals < 1.05))


def test_written_means_are_read_back_by_us_and_by_pocketsphinx(
    acoustic: AcousticModel, speech: SpeechModel, tmp_path: Path
) -> None:
    path = tmp_path / "means"
    path.write_bytes(gaussians_bytes(acoustic.means))
    assert np.array_equal(read_gaussians(path), acoustic.means.astype(np.float32).astype(np.float64))
    if tools_missing():
        pytest.skip("the decode needs espeak-ng and sox")
    # the unchanged means as a voice: pocketsphinx reads our file and hears what it hears without it;
    # means moved far away: it hears something else (so it does read them)
    pcm = _said("white varnished oak", "en-us", tmp_path)
    same = Voice(acoustic.means, acoustic.fingerprint, 1, 60.0, 6000)
    moved = Voice(acoustic.means[:, :, ::-1].copy(), acoustic.fingerprint, 1, 60.0, 6000)  # densities shuffled
    plain, voiced, wrong = (speech.recogniser(v).decode(pcm) for v in (None, same, moved))
    assert plain is not None and voiced is not None and plain.text == voiced.text == "white varnished oak"
    assert wrong is None or wrong.text != plain.text


def test_log_weights_refuse_a_codebook_of_another_size() -> None:
    from cnlmc.speech.sphinx_files import ModelFormatError

    with pytest.raises(ModelFormatError):
        read_log_weights(model_files().acoustic / "sendump", 3, 256)


# ---------------------------------------------------------------- the maths


def test_features_are_the_mean_removed_cepstra_and_their_deltas() -> None:
    ramp = np.outer(np.arange(20.0), np.ones(13)) * 0.5
    c, d, dd = features(ramp)
    assert np.allclose(c.mean(axis=0), 0.0)
    assert np.allclose(d[3:-3], 2.0)  # c[t+2] - c[t-2] on a slope of 0.5 a frame
    assert np.allclose(dd[4:-4], 0.0)  # the slope does not change
    assert np.allclose(d[0], 1.0)  # the first frame repeated: c[2] - c[0]


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 2**31 - 1))
def test_mllr_recovers_a_known_affine_map(seed: int) -> None:
    """Frames that are exactly A mean + b of their Gaussians: MLLR (almost no prior) finds A and b."""
    model, a, b = _tiny_model(seed)
    moved = transformed(model.means, a, b)
    occupancy = np.random.default_rng(seed).uniform(1.0, 5.0, model.means.shape[:3])
    stats = Statistics(occupancy, occupancy[..., None] * moved, frames=int(occupancy.sum()))
    found_a, found_b = mllr(model, stats, prior_frames=1e-9)
    assert np.allclose(found_a, a, atol=1e-5) and np.allclose(found_b, b, atol=1e-5)


def test_the_mllr_prior_keeps_the_identity_without_frames() -> None:
    model, _, _ = _tiny_model(1)
    stats = Statistics(np.zeros(model.means.shape[:3]), np.zeros(model.means.shape), frames=0)
    stats.occupancy[0, 0, 0] = 1e-12  # next to nothing heard
    a, b = mllr(model, stats, prior_frames=5.0)
    assert np.allclose(a, np.eye(model.means.shape[-1])) and np.allclose(b, 0.0)


def test_posteriors_are_the_weighted_gaussians_normalised() -> None:
    from cnlmc.speech.voice import _posteriors

    rng = np.random.default_rng(3)
    frames, means = rng.normal(size=(5, 4)), rng.normal(size=(6, 4))
    variances, log_weights = rng.uniform(0.5, 2.0, (6, 4)), np.log(rng.dirichlet(np.ones(6), size=5))
    found = _posteriors(frames, means, variances, log_weights)
    log_like = np.array(
        [
            [lw[d] - 0.5 * np.sum((f - means[d]) ** 2 / variances[d] + np.log(variances[d])) for d in range(6)]
            for f, lw in zip(frames, log_weights)
        ]
    )
    expected = np.exp(log_like - log_like.max(axis=1, keepdims=True))
    expected /= expected.sum(axis=1, keepdims=True)
    assert np.allclose(found, np.where(expected < 1e-6, 0.0, expected), atol=1e-12)


@pytest.mark.parametrize("snr_db", [None, 30.0, 20.0, 10.0])
def test_a_reading_is_cut_in_its_pauses_quiet_or_noisy(snr_db: float | None) -> None:
    """Five 'sentences' (tones with a short 80 ms stop inside some), half a second apart, clean
    or in white noise: the four cuts fall in the four pauses, not in the stops."""
    from cnlmc.speech.audio import split_at_pauses

    rng = np.random.default_rng(5)
    pieces, pauses, at = [], [], 0
    for number in range(5):
        seconds = rng.uniform(1.2, 2.0)
        t = np.arange(int(RATE * seconds)) / RATE
        tone = 8000 * (0.6 + 0.4 * np.sin(2 * np.pi * 3 * t) ** 2) * np.sin(2 * np.pi * (180 + 30 * number) * t)
        if number % 2:
            tone[len(tone) // 2 : len(tone) // 2 + int(0.08 * RATE)] = 0.0
        pieces.append(tone)
        at += tone.size
        if number < 4:
            pieces.append(np.zeros(RATE // 2))
            pauses.append((at, at + RATE // 2))
            at += RATE // 2
    samples = np.concatenate(pieces)
    if snr_db is not None:
        samples = samples + rng.normal(0.0, 5600 * 10 ** (-snr_db / 20), samples.size)
    pcm = np.clip(samples, -32768, 32767).astype("<i2").tobytes()
    parts = split_at_pauses(pcm, RATE, 5)
    assert parts is not None and len(parts) == 5 and b"".join(parts) == pcm
    cuts = np.cumsum([len(p) // 2 for p in parts])[:-1]
    assert all(start <= cut <= end for cut, (start, end) in zip(cuts, pauses))
    assert split_at_pauses(pcm, RATE, 7) is None  # fewer pauses than that
    assert split_at_pauses(bytes(RATE * 2), RATE, 3) is None  # silence throughout


def test_map_moves_a_mean_by_its_occupancy() -> None:
    means = np.zeros((1, 1, 2, 3))
    occupancy = np.array([[[10.0, 0.0]]])
    sums = np.zeros((1, 1, 2, 3))
    sums[0, 0, 0] = 10.0  # ten frames at 1.0 for the first Gaussian, none for the second
    moved = map_means(means, Statistics(occupancy, sums), prior=10.0)
    assert np.allclose(moved[0, 0, 0], 0.5)  # half way: as many frames as the prior
    assert np.allclose(moved[0, 0, 1], 0.0)  # unheard: unchanged


def _tiny_model(seed: int) -> tuple[AcousticModel, np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    dim = 3
    means = rng.normal(0.0, 2.0, (2, 3, 6, dim))
    variances = rng.uniform(0.5, 2.0, means.shape)
    a = np.eye(dim)[None] + rng.normal(0.0, 0.2, (3, dim, dim))
    b = rng.normal(0.0, 1.0, (3, dim))
    model = AcousticModel(means, variances, np.zeros((3, 6, 4)), ("A", "B"), None, "tiny")  # type: ignore[arg-type]
    return model, a, b


# ---------------------------------------------------------------- the voice file


def test_a_voice_file_round_trips_and_refuses_other_models(acoustic: AcousticModel, tmp_path: Path) -> None:
    voice = Voice(acoustic.means + 0.25, acoustic.fingerprint, 22, 64.0, 6400)
    path = tmp_path / "me.voice"
    path.write_bytes(voice.to_bytes())
    back = Voice.load(path, acoustic)
    assert np.allclose(back.means, voice.means, atol=1e-5) and back.seconds == 64.0
    other = Voice(acoustic.means, "0123456789abcdef", 22, 64.0, 6400)
    path.write_bytes(other.to_bytes())
    with pytest.raises(VoiceError, match="another acoustic model"):
        Voice.load(path, acoustic)
    path.write_text("white varnished oak\n", "utf-8")
    with pytest.raises(VoiceError, match="not a voice file"):
        Voice.load(path, acoustic)
    path.write_bytes(voice.to_bytes()[:5000])  # cut short
    with pytest.raises(VoiceError, match="not a voice file"):
        Voice.load(path, acoustic)
    with pytest.raises(VoiceError, match="a folder"):
        Voice.load(tmp_path, acoustic)
    with pytest.raises(VoiceError, match="no such voice file"):
        Voice.load(tmp_path / "none.voice", acoustic)


def test_the_script_holds_every_spoken_phone_in_plain_english(speech: SpeechModel) -> None:
    script = Script.bundled()
    table = read_dictionary(model_files().dictionary, script.words())
    assert set(table) == script.words()  # every word is an English word of the dictionary
    phones = {p for prons in table.values() for pron in prons for p in pron.split()}
    assert len(phones) == SPOKEN_PHONES
    # everyday English, not the material language: few of the grammar's words (new, off, car, i)
    material_words = speech.grammar.words_used() - {"a", "an", "the", "some", "and", "or", "with"}
    assert len(script.words() & material_words) <= 5, script.words() & material_words


# ---------------------------------------------------------------- enrolling (espeak-ng voices)


def _said(text: str, voice: str, folder: Path, speed: int = 160) -> bytes:
    return read_pcm(synthesize(Utterance(text, voice, speed, False, False), folder, RATE))


@needs_tools
def test_an_enrolled_voice_is_heard_better(speech: SpeechModel, folder: Path) -> None:
    """The female espeak-ng voice, furthest from the model's speakers: after reading the script
    (not the test phrases), the tests' phrases at three speeds are heard right more often."""
    voice_name = "en-us+f3"
    script = Script.bundled()
    pcm = read_pcm(read_aloud(script.sentences, voice_name, 160, folder, RATE))
    voice = enrol_recording(pcm, Aligner(speech.settings, script), script)
    assert voice.seconds > 40 and voice.sentences == len(script.sentences)
    phrases = Phrases.bundled(full=False)
    scorer = Scorer(lexicon_for(), phrases, speech.settings.undo)
    utterances = phrases.utterances((voice_name,), (130, 160, 190), (False,))
    right = {}
    for label, recogniser in (("base", speech.recogniser()), ("enrolled", speech.recogniser(voice))):
        heard = [recogniser.decode(_said(u.text, u.voice, folder, u.speed), refining=u.refinement) for u in utterances]
        right[label] = sum(scorer.ir_equal(u, h.text if h else None) for u, h in zip(utterances, heard))
    print(f"{voice_name}, {len(utterances)} utterances IR-equal: {right}")
    assert right["enrolled"] >= right["base"] + 5 and right["enrolled"] >= 0.7 * len(utterances)


@needs_tools
def test_listen_enrols_then_hears_with_the_voice(folder: Path, tmp_path: Path, acoustic: AcousticModel) -> None:
    reading = read_aloud(Script.bundled().sentences, "en-gb", 160, folder, RATE)
    voice = tmp_path / "me.voice"
    voice.write_bytes(Voice(acoustic.means, "an older model", 1, 30.0, 3000).to_bytes())  # enrolling again replaces it
    done = run_cnlmc("listen", "--enrol", "--from", str(reading), "--voice", str(voice))
    assert done.returncode == 0, done.stderr
    assert voice.is_file() and f"use it with: cnlmc listen --voice {voice}" in done.stderr
    said = synthesize(Utterance("white varnished oak", "en-gb", 160, False, False), folder, RATE)
    heard = run_cnlmc("listen", "--from", str(said), "--voice", str(voice), "--min-confidence", "0")
    assert heard.returncode == 0, heard.stderr
    assert "heard '" in heard.stderr and '"materials"' in heard.stdout


@needs_tools
def test_enrolment_errors_write_nothing(folder: Path, tmp_path: Path) -> None:
    short = synthesize(Utterance("white varnished oak", "en-us", 160, False, False), folder, RATE)
    voice = tmp_path / "short.voice"
    done = run_cnlmc("listen", "--enrol", "--from", str(short), "--voice", str(voice))
    assert done.returncode == 2 and not voice.exists() and "Traceback" not in done.stderr
    notes = tmp_path / "notes.txt"
    notes.write_text("mine\n", "utf-8")
    reading = read_aloud(Script.bundled().sentences, "en-us", 160, folder, RATE)
    refused = run_cnlmc("listen", "--enrol", "--from", str(reading), "--voice", str(notes))
    assert refused.returncode == 2 and "is not a voice file: not replaced" in refused.stderr
    assert notes.read_text("utf-8") == "mine\n"
    unnamed = run_cnlmc("listen", "--enrol", "--from", str(reading))
    assert unnamed.returncode == 2 and "--enrol needs --voice FILE" in unnamed.stderr
    folder_path = run_cnlmc("listen", "--enrol", "--from", str(reading), "--voice", str(tmp_path))
    assert folder_path.returncode == 2 and "not a regular file" in folder_path.stderr
    unused = run_cnlmc("listen", "--enrol", "--from", str(reading), "--voice", str(voice), "-o", "out.json")
    assert unused.returncode == 2 and "-o cannot be used with it" in unused.stderr and not voice.exists()


def test_listen_with_a_voice_file_that_is_not_one(tmp_path: Path) -> None:
    notes = tmp_path / "notes.voice"
    notes.write_text("mine\n", "utf-8")
    wav = tmp_path / "silence.wav"
    if tools_missing():
        pytest.skip("needs sox")
    subprocess.run(["sox", "-n", "-r", str(RATE), "-c", "1", "-b", "16", str(wav), "trim", "0", "1"], check=True)
    done = run_cnlmc("listen", "--from", str(wav), "--voice", str(notes))
    assert done.returncode == 2 and "not a voice file made by cnlmc listen --enrol" in done.stderr
    missing = run_cnlmc("listen", "--from", str(wav), "--voice", str(tmp_path / "none.voice"))
    assert missing.returncode == 2 and "make one with: cnlmc listen --enrol" in missing.stderr


def test_the_enrolment_script_is_printed() -> None:
    done = run_cnlmc("listen", "--enrol-script")
    assert done.returncode == 0
    lines = [line for line in done.stdout.splitlines() if line[:2].strip().isdigit()]
    assert len(lines) == len(Script.bundled().sentences)


def test_serve_refuses_a_voice_file_before_it_starts(tmp_path: Path) -> None:
    pytest.importorskip("aiohttp", reason="the studio needs aiohttp")
    notes = tmp_path / "notes.voice"
    notes.write_text("mine\n", "utf-8")
    done = run_cnlmc("serve", "--port", "0", "--voice", str(notes))
    assert done.returncode == 2 and "not a voice file made by cnlmc listen --enrol" in done.stderr
    assert "Traceback" not in done.stderr


def test_the_studio_hears_with_the_served_voice(acoustic: AcousticModel) -> None:
    from cnlmc.studio.speech import StudioEars

    voice = Voice(acoustic.means, acoustic.fingerprint, 22, 60.0, 6000)
    ears = StudioEars(lexicon_for(), (), voice)
    ears._load()
    assert ears.recogniser.voice is voice


@needs_tools
def test_enrolling_at_the_microphone_prompts_each_sentence(speech: SpeechModel, folder: Path) -> None:
    """enrol_live, as `listen --enrol` runs it at the microphone, fed the sentences as recorded
    utterances: the first sentence comes as two (a pause inside it): it is asked for again and the
    two are followed joined; the second is a 50 ms click, twice: it is left out, and said so."""
    from cnlmc.speech.enrol import enrol_live

    script = Script.bundled()
    first = script.sentences[0].split()
    halves = [_said(" ".join(first[:4]), "en-us+m3", folder), _said(" ".join(first[4:]), "en-us+m3", folder)]
    click = b"\x00\x10" * 800
    rest = [_said(sentence, "en-us+m3", folder) for sentence in script.sentences[2:]]
    told: list[str] = []
    voice = enrol_live(iter([*halves, click, click, *rest]), Aligner(speech.settings, script), script, told.append)
    count = len(script.sentences)
    assert voice.sentences == count - 1
    assert told[:2] == [f"[1/{count}] read: {script.sentences[0]}", f"[1/{count}] read again: {script.sentences[0]}"]
    assert told[2:5] == [
        f"[2/{count}] read: {script.sentences[1]}",
        f"[2/{count}] read again: {script.sentences[1]}",
        f"[2/{count}] could not follow that sentence; going on without it",
    ]
    assert told[-1].endswith(script.sentences[-1])
