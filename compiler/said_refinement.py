"""Words said as a refinement of a document (the studio's refine box, a spoken utterance after the
first): the line to add below its last material.

Describing words alone start a material of their own (cnlmc.implied: 'purple' = purple paint), but
said as a refinement they mean a change of the material there: they are added as the change line
'make it purple' (teaching.toml [politeness] changes). Anything else is added as it was said. The
rule lives with the session API (`cnlmc.api.refined`, also what `Session.refine` uses)."""

from __future__ import annotations

from .api import refined

__all__ = ["refined"]
