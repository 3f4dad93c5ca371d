"""A speaker's voice: the acoustic model's Gaussian means adapted to one speaker from sentences read
aloud (`cnlmc listen --enrol`), the way dictation systems enrol a user.

The bundled en-US model is speaker-independent, trained on other people's speech; a voice far from
its speakers (a high voice, a British one, a synthesiser) is misheard whatever the grammar
(docs/speech.md). Adaptation, in two classic steps on the frames of the read sentences aligned to
their known words:

1. **MLLR** (C. J. Leggetter, P. C. Woodland, "Maximum likelihood linear regression for speaker
   adaptation of continuous density HMMs", Computer Speech and Language 9, 1995): one affine map
   per feature stream, mean' = A mean + b, moves every Gaussian, also those the sentences never
   reach; each row is solved from the Gaussians' occupancies, pulled towards the identity by
   `mllr_prior_frames` frames' worth (few sentences cannot make it singular).
2. **MAP** (J.-L. Gauvain, C.-H. Lee, "Maximum a posteriori estimation for multivariate Gaussian
   mixture observations of Markov chains", IEEE Trans. Speech and Audio Processing 2(2), 1994):
   each Gaussian's mean moves from its MLLR value towards the mean of the frames it scores, by its
   occupancy against `map_prior` frames: well-heard sounds move most, unheard ones keep MLLR's.

Occupancies are the posteriors of each frame's codebook Gaussians under its aligned senone's
mixture weights. Variances and weights are kept. Pure numpy here; the alignment is cnlmc.speech.enrol."""

from __future__ import annotations

import hashlib
import io
import json
import struct
import tokenize
import zipfile
import zlib
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from .sphinx_files import FeatureSpec, ModelFormatError, read_ciphones, read_gaussians, read_log_weights

VOICE_FILE_ERRORS = (ValueError, KeyError, EOFError, TypeError, AttributeError, zipfile.BadZipFile, zlib.error)

VARIANCE_FLOOR = 1e-4  # pocketsphinx's varfloor: it floors the model's variances at this when loading
FORMAT = "cnlmc-voice"
VERSION = 1
MIN_POSTERIOR = 1e-6  # smaller shares of a frame are left out of the statistics


class VoiceError(ValueError):
    """A voice file that cannot be used, or a recording that cannot be enrolled: what to do."""


@dataclass(frozen=True)
class AcousticModel:
    """The parts of the acoustic model adaptation needs."""

    means: np.ndarray  # [codebook, stream, density, dimension]
    variances: np.ndarray  # the same shape, floored
    log_weights: np.ndarray  # [stream, density, senone]
    ciphones: tuple[str, ...]  # codebook i belongs to ciphones[i] (one codebook per phone)
    spec: FeatureSpec
    fingerprint: str  # of the means file: a voice fits only the model it was made from

    @classmethod
    def read(cls, folder: Path) -> AcousticModel:
        spec = FeatureSpec.read(folder / "feat.params")
        if spec.kind != "1s_c_d_dd" or spec.streams != 3:
            raise ModelFormatError(f"{folder}: features {spec.kind} in {spec.streams} streams are not supported")
        means = read_gaussians(folder / "means")
        variances = np.maximum(read_gaussians(folder / "variances"), VARIANCE_FLOOR)
        n_mgau, n_feat, n_density, _ = means.shape
        ciphones = read_ciphones(folder / "mdef")
        if len(ciphones) != n_mgau or variances.shape != means.shape:
            raise ModelFormatError(f"{folder}: not a phonetically tied model (one codebook per phone)")
        weights = read_log_weights(folder / "sendump", n_feat, n_density)
        digest = hashlib.sha256((folder / "means").read_bytes()).hexdigest()[:16]
        return cls(means, variances, weights, ciphones, spec, digest)

    def codebook(self, phone: str) -> int:
        return self.ciphones.index(phone)


@lru_cache(maxsize=2)
def acoustic_model(folder: Path) -> AcousticModel:
    """The acoustic model in `folder` (VoiceError when it is not one adaptation can read)."""
    try:
        return AcousticModel.read(folder)
    except (ModelFormatError, struct.error, OSError, UnicodeDecodeError) as exc:
        raise VoiceError(f"the acoustic model in {folder} cannot be adapted to a voice: {exc}") from None


@dataclass(frozen=True)
class Aligned:
    """One read sentence: its cepstra and, per frame, the codebook and senone it was aligned to."""

    cepstra: np.ndarray  # [frame, ceplen], as the recogniser's front end computed them
    codebooks: np.ndarray  # [frame]
    senones: np.ndarray  # [frame]


def features(cepstra: np.ndarray) -> list[np.ndarray]:
    """The three streams of 1s_c_d_dd: cepstra less their utterance mean (batch CMN), deltas
    c[t+2] - c[t-2], double deltas d[t+1] - d[t-1]; the ends repeat the first and last frame."""
    c = cepstra - cepstra.mean(axis=0)
    padded = np.pad(c, ((3, 3), (0, 0)), mode="edge")
    frames = len(c)

    def at(shift: int) -> np.ndarray:
        return padded[3 + shift : 3 + shift + frames]

    return [c, at(2) - at(-2), (at(3) - at(-1)) - (at(1) - at(-3))]


@dataclass
class Statistics:
    """Per Gaussian: its occupancy (frames' worth) and the occupancy-weighted sum of its frames."""

    occupancy: np.ndarray  # [codebook, stream, density]
    sums: np.ndarray  # [codebook, stream, density, dimension]
    frames: int = 0

    @classmethod
    def of(cls, model: AcousticModel, aligned: list[Aligned], means: np.ndarray) -> Statistics:
        stats = cls(np.zeros(means.shape[:3]), np.zeros(means.shape))
        for sentence in aligned:
            stats.add(model, sentence, means)
        return stats

    def add(self, model: AcousticModel, sentence: Aligned, means: np.ndarray) -> None:
        streams = features(sentence.cepstra)
        self.frames += len(sentence.codebooks)
        for codebook in np.unique(sentence.codebooks):
            at = sentence.codebooks == codebook
            for stream, observed in enumerate(streams):
                frames = observed[at]
                posterior = _posteriors(
                    frames,
                    means[codebook, stream],
                    model.variances[codebook, stream],
                    model.log_weights[stream][:, sentence.senones[at]].T,
                )
                self.occupancy[codebook, stream] += posterior.sum(axis=0)
                self.sums[codebook, stream] += posterior.T @ frames


def _posteriors(frames: np.ndarray, means: np.ndarray, variances: np.ndarray, log_weights: np.ndarray) -> np.ndarray:
    """[frame, density]: each frame's share among its codebook's Gaussians, weighted by its senone."""
    precision = 1.0 / variances
    distance = (frames**2) @ precision.T - 2.0 * frames @ (means * precision).T + np.sum(means**2 * precision, axis=1)
    log_like = -0.5 * (distance + np.sum(np.log(variances), axis=1)) + log_weights
    log_like -= log_like.max(axis=1, keepdims=True)
    shares = np.exp(log_like)
    shares /= shares.sum(axis=1, keepdims=True)
    return np.where(shares < MIN_POSTERIOR, 0.0, shares)


def mllr(model: AcousticModel, stats: Statistics, prior_frames: float) -> tuple[np.ndarray, np.ndarray]:
    """Per stream, the affine map (A [stream, dim, dim], b [stream, dim]) of the means that makes
    the aligned frames likeliest (diagonal covariances: each row apart), pulled towards the identity
    by `prior_frames` frames' worth (so that no frames at all give the identity)."""
    _, n_feat, _, dim = model.means.shape
    a = np.zeros((n_feat, dim, dim))
    b = np.zeros((n_feat, dim))
    for stream in range(n_feat):
        occupancy = stats.occupancy[:, stream].reshape(-1)
        means = model.means[:, stream].reshape(-1, dim)
        extended = np.hstack([np.ones((len(means), 1)), means])  # [1, mean]: the bias first
        sums = stats.sums[:, stream].reshape(-1, dim)
        precision = 1.0 / model.variances[:, stream].reshape(-1, dim)
        for row in range(dim):
            weight = occupancy * precision[:, row]
            g = (extended * weight[:, None]).T @ extended
            k = extended.T @ (sums[:, row] * precision[:, row])
            typical = np.sum(precision[:, row] * np.sum(extended**2, axis=1)) / len(means) / (dim + 1)
            strength = prior_frames * typical  # a frame's worth of g (on average over the model)
            identity = np.zeros(dim + 1)
            identity[row + 1] = 1.0
            solved = np.linalg.solve(g + strength * np.eye(dim + 1), k + strength * identity)
            b[stream, row], a[stream, row] = solved[0], solved[1:]
    return a, b


def transformed(means: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    moved: np.ndarray = np.einsum("fij,cfdj->cfdi", a, means) + b[None, :, None, :]
    return moved


def map_means(means: np.ndarray, stats: Statistics, prior: float) -> np.ndarray:
    """Each mean moved towards its frames' mean by its occupancy against `prior` frames."""
    moved: np.ndarray = (prior * means + stats.sums) / (prior + stats.occupancy[..., None])
    return moved


def adapted_means(
    model: AcousticModel, aligned: list[Aligned], mllr_prior_frames: float, map_prior: float
) -> np.ndarray:
    """MLLR, then MAP from the MLLR means (the frames' shares counted again under them)."""
    a, b = mllr(model, Statistics.of(model, aligned, model.means), mllr_prior_frames)
    moved = transformed(model.means, a, b)
    return map_means(moved, Statistics.of(model, aligned, moved), map_prior)


@dataclass(frozen=True)
class Voice:
    """An enrolled voice: adapted means for the acoustic model with `fingerprint`."""

    means: np.ndarray
    fingerprint: str
    sentences: int
    seconds: float
    frames: int

    def to_bytes(self) -> bytes:
        meta = {
            "format": FORMAT,
            "version": VERSION,
            "model": self.fingerprint,
            "sentences": self.sentences,
            "seconds": round(self.seconds, 2),
            "frames": self.frames,
        }
        buffer = io.BytesIO()
        np.savez_compressed(buffer, means=self.means.astype(np.float32), meta=np.array(json.dumps(meta)))
        return buffer.getvalue()

    @classmethod
    def load(cls, path: str | Path, model: AcousticModel) -> Voice:
        """A voice file made by `cnlmc listen --enrol` for this acoustic model (VoiceError otherwise)."""
        meta, means = _read_voice_file(path)
        again = f"enrol again: cnlmc listen --enrol --voice {path}"
        if meta.get("format") != FORMAT or meta.get("version") != VERSION:
            raise VoiceError(f"{path}: made by another version of cnlmc; {again}")
        if meta.get("model") != model.fingerprint or means.shape != model.means.shape:
            raise VoiceError(f"{path}: made for another acoustic model; {again}")
        if not np.all(np.isfinite(means)):
            raise VoiceError(f"{path}: the voice file is damaged (values that are not numbers); {again}")
        try:
            return cls(
                means, str(meta["model"]), _count(meta["sentences"]), _number(meta["seconds"]), _count(meta["frames"])
            )
        except VOICE_FILE_ERRORS:
            raise VoiceError(f"{path}: the voice file is damaged; {again}") from None


def _count(value: object) -> int:
    if not isinstance(value, int) or value < 0:
        raise ValueError(value)
    return value


def _number(value: object) -> float:
    if not isinstance(value, int | float):
        raise ValueError(value)
    return float(value)


def is_voice_file(path: str | Path) -> bool:
    """Whether `path` is a voice file of cnlmc's, of any version or model (enrolling again replaces it)."""
    try:
        meta, _ = _read_voice_file(path)
    except VoiceError:
        return False
    return meta.get("format") == FORMAT


def _read_voice_file(path: str | Path) -> tuple[dict[str, object], np.ndarray]:
    """The metadata and the means of a voice file (VoiceError for anything that is not one)."""
    try:
        with np.load(path, allow_pickle=False) as data:
            meta = json.loads(str(data["meta"]))
            means = np.asarray(data["means"], dtype=np.float64)
    except FileNotFoundError:
        raise VoiceError(f"{path}: no such voice file; make one with: cnlmc listen --enrol --voice {path}") from None
    except IsADirectoryError:
        raise VoiceError(f"{path}: a folder, not a voice file") from None
    except OSError as exc:
        raise VoiceError(f"{path}: cannot read the voice file ({exc.strerror or exc})") from None
    except (*VOICE_FILE_ERRORS, tokenize.TokenError):
        raise VoiceError(f"{path}: not a voice file made by cnlmc listen --enrol") from None
    if not isinstance(meta, dict):
        raise VoiceError(f"{path}: not a voice file made by cnlmc listen --enrol")
    return meta, means
