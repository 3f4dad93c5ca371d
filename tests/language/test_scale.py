"""Large inputs (#13: a 100k-line file took 85 s, 5.7 GB and wrote 638 MB): what keeps them linear.

Timing and memory are measured by bench/scale_bench.py; these tests pin the behaviour behind it.
"""

import gc
import json

from cnlmc.analyze import analyze, analyze_to_ir, to_ir
from cnlmc.api import compile_source, cyclic_gc_paused, lexicon_for
from cnlmc.document import parse_document
from cnlmc.state import Context
from tests.helpers import run_cnlmc as cnlmc

PHRASES = ("aluminum", "red or blue anodized aluminum", "oak with a glossy white varnish", "brushd steel", "darker")
SOURCE = "".join(f"m{n}: {PHRASES[n % 3]}\n" if n % 7 else f"{PHRASES[3 + n % 2]}\n" for n in range(200))


def test_the_streamed_ir_is_the_ir_of_the_states():
    """analyze_to_ir (the CLI's path: each state to IR at once, then let go) gives exactly what
    analyze + to_ir (the language server's path, which keeps the stages) give."""
    lexicon = lexicon_for()
    ctx = Context(lexicon, filename="big.cnl")
    states, diags = analyze(parse_document(SOURCE, lexicon, "big.cnl"), ctx)
    doc = parse_document(SOURCE, lexicon, "big.cnl")
    streamed, streamed_diags = analyze_to_ir(doc, ctx)
    assert streamed == to_ir(states, diags, ctx)
    assert streamed_diags == diags
    assert doc.items == []  # the syntax tree is not kept


def test_compile_without_stages_keeps_only_the_ir():
    full = compile_source(SOURCE, "big.cnl")
    lean = compile_source(SOURCE, "big.cnl", keep_stages=False)
    assert lean.ir == full.ir and lean.diagnostics == full.diagnostics
    assert lean.source_document is None and lean.states == []
    assert full.source_document is not None and len(full.states) == len(full.materials)


def test_the_collector_is_paused_only_while_compiling():
    assert gc.isenabled()
    with cyclic_gc_paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    gc.disable()
    try:
        with cyclic_gc_paused():
            pass
        assert not gc.isenabled()  # a caller that had it off keeps it off
    finally:
        gc.enable()


def test_the_ir_file_has_one_line_per_material(tmp_path):
    source = tmp_path / "many.cnl"
    source.write_text("".join(f"m{n}: {PHRASES[n % 3]}\n" for n in range(300)))
    out = tmp_path / "many.ir.json"
    r = cnlmc("compile", str(source), "-o", str(out))
    assert r.returncode == 0, r.stderr
    text = out.read_text()
    ir = json.loads(text)
    assert ir == compile_source(source.read_text(), str(source)).ir
    material_lines = [line for line in text.splitlines() if line.startswith('    {"name": ')]
    assert len(material_lines) == len(ir["materials"]) == 400  # 'red or blue' is two materials
    assert max(len(line.encode()) for line in material_lines) < 8192  # bounded per material
