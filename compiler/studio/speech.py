"""Speech in the studio (issue #18): the page records an utterance while its microphone button is
on and sends it (16-bit mono PCM at the recogniser's rate, base64) with `hear`; the server
recognises it with the lexicon's grammar (cnlmc.speech) and applies it as `cnlmc listen` does:
while the document names no material the utterance becomes the document, then utterances refine
it, 'undo' steps back; below the confidence threshold nothing changes and the page shows what was
heard and the alternatives. The silence before and after the speech is cut first
(cnlmc.speech.audio.speech_span), as `cnlmc listen` cuts a recording at its pauses.

With `cnlmc serve --voice FILE` the recogniser is adapted to an enrolled speaker (cnlmc.speech.voice).
One recogniser serves every tab (loaded on the first utterance: pocketsphinx is an optional extra,
imported only then); a lock keeps one decode at a time."""

from __future__ import annotations

import threading
from typing import Any

from ..lexicon import Lexicon
from ..speech.settings import SpeechSettings


class StudioEars:
    def __init__(self, lexicon: Lexicon, folders: tuple[str, ...] = (), voice: Any = None) -> None:
        self.lexicon = lexicon
        self.folders = folders
        self.voice = voice  # an enrolled voice (cnlmc.speech.voice.Voice: `cnlmc serve --voice`), or None
        self.lock = threading.Lock()
        self.settings = SpeechSettings.bundled()  # the threshold, 'undo', the rate the page records at
        self.rate = self.settings.sample_rate
        self.recogniser: Any = None

    def hear(self, pcm: bytes, refining: bool) -> Any:
        """The hypothesis of one utterance (cnlmc.speech.recogniser.Hypothesis, None when no
        phrase of the language was heard). ValueError when speech input is not installed."""
        with self.lock:
            self._load()
            from ..speech.audio import speech_span

            return self.recogniser.decode(speech_span(pcm, self.rate), refining=refining)

    def _load(self) -> None:
        if self.recogniser is not None:
            return
        from ..speech.model import SpeechModel
        from ..speech.recogniser import SpeechUnavailable

        try:
            self.recogniser = SpeechModel.of(self.lexicon, self.folders, self.settings).recogniser(self.voice)
        except SpeechUnavailable as exc:
            raise ValueError(str(exc)) from None
