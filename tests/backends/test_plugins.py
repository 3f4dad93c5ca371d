"""Third-party targets register through the entry point group 'cnlmc.backends'."""

import subprocess
import sys
import textwrap


def make_plugin(root):
    (root / "toy_target.py").write_text(
        textwrap.dedent("""
        from cnlmc.backends.capabilities import ALL_FEATURES, EmitResult
        from cnlmc.backends.registry import Artifact
        NAME = "toy"
        DESCRIPTION = "names and base colours as text"
        CAPABILITIES = {f: ("exact", "") for f in ALL_FEATURES}
        def emit(ir, options):
            lines = [f"{m['name']} {m['params']['base_color']}" for m in ir["materials"]]
            return EmitResult([Artifact("toy.txt", "\\n".join(lines) + "\\n")])
    """)
    )
    info = root / "toy_target-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: toy-target\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[cnlmc.backends]\ntoy = toy_target\n")


def cnlmc(root, *args, stdin=None):
    env_path = f"{root}"
    code = f"import sys; sys.path.insert(0, {env_path!r}); from cnlmc.cli import main; sys.exit(main(sys.argv[1:]))"
    return subprocess.run([sys.executable, "-c", code, *args], input=stdin, capture_output=True, text=True, timeout=60)


def test_an_installed_plugin_is_a_target(tmp_path):
    make_plugin(tmp_path)
    listed = cnlmc(tmp_path, "targets")
    assert "toy" in listed.stdout and "toy_target" in listed.stdout
    assert "names and base colours as text" in listed.stdout  # each target with its description
    r = cnlmc(tmp_path, "compile", "-", "--target", "toy", stdin="blue plastic\n")
    assert r.returncode == 0, r.stderr
    assert r.stdout == "blue_plastic [0.0, 0.0, 1.0]\n"


def test_a_misspelled_plugin_target_gets_did_you_mean(tmp_path):
    make_plugin(tmp_path)
    r = cnlmc(tmp_path, "compile", "-", "--target", "tooy", stdin="steel\n")
    assert r.returncode == 2 and "did you mean 'toy'?" in r.stderr
