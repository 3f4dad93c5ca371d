"""Speech input: `cnlmc listen` (issue #18).

The recogniser (pocketsphinx, offline, CPU) is constrained to the phrases the compiler accepts:
its JSGF grammar is generated from the same lexicon (cnlmc.speech.grammar), with pronunciations
from the CMU dictionary, stdlib/speech/pronunciations.toml and a lexicon folder's own
speech/pronunciations.toml (cnlmc.speech.pronounce). Recognised phrases are compiled as typed
text is (cnlmc.speech.listen). pocketsphinx and the audio library load only when `listen` runs.
"""
