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
    assert r.stdout == "blue_plastic [0.000911, 0.056128, 0.73791]\n"  # the survey's blue #0343df


def test_a_misspelled_plugin_target_gets_did_you_mean(tmp_path):
    make_plugin(tmp_path)
    r = cnlmc(tmp_path, "compile", "-", "--target", "tooy", stdin="steel\n")
    assert r.returncode == 2 and "did you mean 'toy'?" in r.stderr


def make_contract_plugin(root):
    """A plugin written against the contract: a Target object with declared options."""
    (root / "names_target.py").write_text(
        textwrap.dedent("""
        from cnlmc.backends.base import Artifact, Option, Target, emit_each
        from cnlmc.backends.capabilities import ALL_FEATURES
        class NamesTarget(Target):
            name = "names"
            description = "material names, one file each"
            capabilities = {f: ("exact", "") for f in ALL_FEATURES}
            options = (Option("separator", str, "=", doc="between name and IOR"),)
            def emit(self, document, options):
                text = lambda m: f"{m.name}{options.separator}{m.params.ior}\\n"
                return emit_each(self, document, lambda m: [Artifact(m.name + ".txt", text(m))])
        TARGET = NamesTarget()
    """)
    )
    info = root / "names_target-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: names-target\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[cnlmc.backends]\nnames = names_target\n")


def test_a_plugin_target_object_gets_its_options_parsed(tmp_path):
    make_contract_plugin(tmp_path)
    r = cnlmc(tmp_path, "compile", "-", "--target", "names", "--option", "separator=:", stdin="red plastic\n")
    assert r.returncode == 0, r.stderr
    assert r.stdout == "red_plastic:1.4905\n"
    r = cnlmc(tmp_path, "compile", "-", "--target", "names", "--option", "seperator=:", stdin="red plastic\n")
    assert r.returncode == 2 and "did you mean 'separator'?" in r.stderr


def test_a_plugin_brings_a_subcommand(tmp_path):
    (tmp_path / "hello_command.py").write_text(
        textwrap.dedent("""
        from cnlmc.backends.base import Command
        class Hello(Command):
            name = "hello"
            help = "greet someone"
            def add_arguments(self, parser):
                parser.add_argument("who")
            def run(self, args):
                print(f"hello {args.who}")
                return 0
    """)
    )
    info = tmp_path / "hello_command-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: hello-command\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[cnlmc.commands]\nhello = hello_command:Hello\n")
    r = cnlmc(tmp_path, "hello", "world")
    assert r.returncode == 0 and r.stdout == "hello world\n", r.stderr
    r = cnlmc(tmp_path, "helo", "world")
    assert r.returncode == 2 and "invalid choice: 'helo'" in r.stderr


def test_a_broken_plugin_does_not_hide_the_other_targets(tmp_path):
    (tmp_path / "broken_target.py").write_text("raise RuntimeError('half-installed')\n")
    info = tmp_path / "broken_target-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text("Metadata-Version: 2.1\nName: broken-target\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text("[cnlmc.backends]\nbroken = broken_target\n")
    listed = cnlmc(tmp_path, "targets")
    assert listed.returncode == 0, listed.stderr
    assert "broken" in listed.stdout and "cannot load: RuntimeError: half-installed" in listed.stdout
    assert "glsl" in listed.stdout and "materialx" in listed.stdout
