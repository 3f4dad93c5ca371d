"""The files of a Sphinx acoustic model that speaker adaptation reads and writes, read with numpy:
the Gaussian codebooks (`means`, `variances`: Sphinx-3 binary parameter files), the quantised
mixture weights (`sendump`), the context-independent phones of the binary model definition
(`mdef`), the feature settings (`feat.params`) and the cepstra pocketsphinx logs (`mfclogdir`).

Formats as pocketsphinx 5 reads them (its gauden, ptm_mgau, bin_mdef and feat modules): a Sphinx-3
parameter file is a text header ("s3", "key value" lines, "endhdr"), a 32-bit byte-order word,
the dimensions and the float32 values; our own files are written without the optional checksum."""

from __future__ import annotations

import struct
from dataclasses import dataclass
from pathlib import Path

import numpy as np

BYTE_ORDER_MAGIC = 0x11223344
HEADER_END = b"endhdr\n"
LOG_BASE = 1.0001  # pocketsphinx's log base (logbase)
WEIGHT_SHIFT = 10  # sendump holds -log weights shifted right by this many bits (SENSCR_SHIFT)


class ModelFormatError(ValueError):
    """An acoustic model file is not in the format adaptation reads."""


def read_gaussians(path: Path) -> np.ndarray:
    """A means or variances file as float64 [codebook, stream, density, dimension] (every stream
    the same length: the 3 x 13 of the bundled model's features)."""
    data = path.read_bytes()
    try:
        offset = data.index(HEADER_END) + len(HEADER_END)
    except ValueError:
        raise ModelFormatError(f"{path}: no Sphinx-3 header") from None
    order = _byte_order(data, offset, path)
    offset += 4
    n_mgau, n_feat, n_density = struct.unpack_from(order + "3i", data, offset)
    offset += 12
    lengths = struct.unpack_from(order + f"{n_feat}i", data, offset)
    offset += 4 * n_feat
    (count,) = struct.unpack_from(order + "i", data, offset)
    offset += 4
    if len(set(lengths)) != 1 or count != n_mgau * n_feat * n_density * lengths[0]:
        raise ModelFormatError(f"{path}: streams of unequal length {lengths} are not supported")
    values = np.frombuffer(data, dtype=order + "f4", count=count, offset=offset)
    return values.astype(np.float64).reshape(n_mgau, n_feat, n_density, lengths[0])


def gaussians_bytes(values: np.ndarray) -> bytes:
    """[codebook, stream, density, dimension] as a Sphinx-3 parameter file pocketsphinx reads."""
    n_mgau, n_feat, n_density, length = values.shape
    head = b"s3\nversion 1.0\n"
    head += b" " * (-(len(head) + len(HEADER_END)) % 4) + HEADER_END  # the values 4-byte aligned
    dims = struct.pack("<I3i", BYTE_ORDER_MAGIC, n_mgau, n_feat, n_density)
    dims += struct.pack(f"<{n_feat}i", *[length] * n_feat) + struct.pack("<i", values.size)
    return head + dims + np.ascontiguousarray(values, dtype="<f4").tobytes()


def read_log_weights(path: Path, n_feat: int, n_density: int) -> np.ndarray:
    """The mixture weights of `sendump` as natural logs, [stream, density, senone]."""
    data = path.read_bytes()
    offset, order = 0, "<"
    (length,) = struct.unpack_from(order + "i", data, offset)
    if not 0 < length < 1000:
        order = ">"
    info: dict[str, str] = {}
    for index in range(1000):
        (length,) = struct.unpack_from(order + "i", data, offset)
        offset += 4
        if length == 0:
            break
        text = data[offset : offset + length].rstrip(b"\0").decode("ascii", "replace")
        offset += length
        if index >= 2:  # after the title and the header: "key value" strings
            key, _, value = text.partition(" ")
            info[key] = value
    if int(info.get("cluster_count", "0")) != 0:
        raise ModelFormatError(f"{path}: clustered (4-bit) mixture weights are not supported")
    rows, columns = struct.unpack_from(order + "2i", data, offset)
    offset += 8
    if rows != n_density:
        raise ModelFormatError(f"{path}: {rows} densities, the codebooks have {n_density}")
    quantised = np.frombuffer(data, dtype=np.uint8, count=n_feat * rows * columns, offset=offset)
    scale = float((1 << WEIGHT_SHIFT) * np.log(LOG_BASE))
    weights: np.ndarray = quantised.astype(np.float64).reshape(n_feat, rows, columns) * -scale
    return weights


def read_ciphones(path: Path) -> tuple[str, ...]:
    """The context-independent phones of a binary model definition, in codebook order."""
    data = path.read_bytes()
    if data[:4] not in (b"BMDF", b"FDMB"):
        raise ModelFormatError(f"{path}: not a binary model definition")
    order = "<" if data[:4] == b"BMDF" else ">"
    (length,) = struct.unpack_from(order + "i", data, 8)
    offset = 12 + length
    n_ciphone = struct.unpack_from(order + "i", data, offset)[0]
    offset += 10 * 4  # n_ciphone ... sil: ten int32 counts
    names = data[offset:].split(b"\0", n_ciphone)[:n_ciphone]
    return tuple(name.decode("ascii") for name in names)


@dataclass(frozen=True)
class FeatureSpec:
    """What feat.params says about the features: cepstra per frame and how they are split."""

    kind: str  # e.g. 1s_c_d_dd: the cepstra, their deltas and double deltas
    streams: int  # subvectors scored apart (svspec)
    ceplen: int

    @classmethod
    def read(cls, path: Path) -> FeatureSpec:
        words = path.read_text("ascii").split()
        params = dict(zip(words[::2], words[1::2]))
        streams = len(params.get("-svspec", "").split("/")) if "-svspec" in params else 1
        return cls(params.get("-feat", "1s_c_d_dd"), streams, int(params.get("-ceplen", "13")))


def read_cepstra(path: Path, ceplen: int) -> np.ndarray:
    """A cepstrum log file (mfclogdir) as [frame, ceplen]."""
    data = path.read_bytes()
    for order in "<>":
        (count,) = struct.unpack_from(order + "i", data, 0)
        if 4 + 4 * count == len(data) and count % ceplen == 0:
            values = np.frombuffer(data, dtype=order + "f4", count=count, offset=4)
            return values.astype(np.float64).reshape(-1, ceplen)
    raise ModelFormatError(f"{path}: not a cepstrum file")


def _byte_order(data: bytes, offset: int, path: Path) -> str:
    for order in "<>":
        if struct.unpack_from(order + "I", data, offset)[0] == BYTE_ORDER_MAGIC:
            return order
    raise ModelFormatError(f"{path}: no byte-order word after the header")
