"""espeak-ng's IPA read as pocketsphinx's ARPAbet phones (stdlib/speech/ipa_arpabet.toml).

espeak-ng is GPL: it runs as an external program (`espeak-ng -q --ipa`), never linked; it makes
pronunciations for words the CMU dictionary lacks (scripts/gen_pronunciations.py, committed as data,
and at run time for a user lexicon's new words when it is installed).
"""

from __future__ import annotations

import shutil
import subprocess
import tomllib
from dataclasses import dataclass
from importlib import resources

VOICES = ("en-us", "en-gb")  # American and British pronunciations (aluminum / aluminium)


@dataclass(frozen=True)
class IpaTable:
    """IPA symbol -> ARPAbet phones, matched longest first; `ignore` marks carry no phone."""

    phones: dict[str, str]
    ignore: frozenset[str]

    @classmethod
    def bundled(cls) -> IpaTable:
        text = resources.files("cnlmc.stdlib").joinpath("speech").joinpath("ipa_arpabet.toml").read_text("utf-8")
        data = tomllib.loads(text)
        return cls(dict(data["phones"]), frozenset(data["ignore"]))

    def arpabet(self, ipa: str) -> str | None:
        """'ˈænədˌaɪzd' -> 'AE N AH D AY Z D'; None when a symbol has no phone here."""
        longest = max(len(s) for s in self.phones)
        out: list[str] = []
        at = 0
        while at < len(ipa):
            if ipa[at] in self.ignore or ipa[at].isspace():
                at += 1
                continue
            for size in range(min(longest, len(ipa) - at), 0, -1):
                phones = self.phones.get(ipa[at : at + size])
                if phones is not None:
                    out.extend(phones.split())
                    at += size
                    break
            else:
                return None
        return " ".join(out) or None


def espeak_available() -> bool:
    return shutil.which("espeak-ng") is not None


def espeak_ipa(words: list[str], voice: str) -> list[str]:
    """Each word's IPA from espeak-ng in `voice` (one process for the list; one line per word)."""
    done = subprocess.run(
        ["espeak-ng", "-q", "--ipa", "-v", voice, "--stdin"],
        input="\n".join(f"{w}." for w in words),  # a full stop ends each clause: one IPA line each
        capture_output=True,
        text=True,
        check=True,
        timeout=120,
    )
    lines = [line.strip() for line in done.stdout.splitlines() if line.strip()]
    if len(lines) != len(words):
        return [_one_ipa(w, voice) for w in words]
    return lines


def _one_ipa(word: str, voice: str) -> str:
    done = subprocess.run(
        ["espeak-ng", "-q", "--ipa", "-v", voice, word], capture_output=True, text=True, check=True, timeout=30
    )
    return done.stdout.strip()


def espeak_pronunciations(words: list[str], table: IpaTable) -> dict[str, list[str]]:
    """word -> its distinct ARPAbet pronunciations in the American and British voices."""
    result: dict[str, list[str]] = {w: [] for w in words}
    for voice in VOICES:
        for word, ipa in zip(words, espeak_ipa(words, voice)):
            phones = table.arpabet(ipa)
            if phones and phones not in result[word]:
                result[word].append(phones)
    return {w: p for w, p in result.items() if p}
