"""The import layers: the API does not drag the command line in, the code tables are plain data
at the ground, and the layer contracts of pyproject.toml hold (``lint-imports``)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from xaml3d.render import accel

ROOT = Path(__file__).resolve().parent.parent


def _modules_after(code: str) -> set[str]:
    env = {k: v for k, v in os.environ.items() if k != accel.ENV}
    out = subprocess.run(
        [sys.executable, "-c", code + "; import sys; print(' '.join(sorted(sys.modules)))"],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stderr
    return set(out.stdout.split())


def test_load_imports_neither_click_nor_numba_nor_the_cli():
    mods = _modules_after("import xaml3d; xaml3d.load('samples/cube.xaml')")
    assert "xaml3d.pipeline" in mods  # the probe really loaded a scene
    assert "click" not in mods
    assert "numba" not in mods
    assert sorted(m for m in mods if m.startswith("xaml3d.cli")) == []


def test_import_contracts_hold():
    """pyproject.toml's import-linter contracts (docs/architecture.md): one direction of
    imports, the renderer and exporters free of the reader, nothing importing the CLI."""
    lint = Path(sys.executable).with_name("lint-imports")
    cmd = [str(lint)] if lint.exists() else [sys.executable, "-m", "importlinter.cli"]
    out = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
    assert "0 broken" in out.stdout


def test_every_command_line_module_is_in_the_contracts():
    import tomllib

    config = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]
    layers = config["contracts"][0]["layers"]
    cli_layer = {m.strip() for m in layers[0].split(":")}
    (no_cli,) = [c for c in config["contracts"] if "imports the command line" in c["name"]]
    forbidden = set(no_cli["forbidden_modules"])
    modules = {f"xaml3d.{p.stem}" for p in (ROOT / "xaml3d").glob("cli*.py")}
    assert modules <= cli_layer and modules <= forbidden, modules - (cli_layer & forbidden)


def test_a_png_render_does_not_import_the_svg_writer():
    """The SVG writer's escaping imports urllib.request, http.client and email (15-35 ms of
    start-up): the render command's modules import it only when an SVG is written."""
    mods = _modules_after(
        "import xaml3d.cli, xaml3d.cli_render, xaml3d.cli_batch, xaml3d.cli_render_extras"
    )
    assert "xaml3d.cli_render_extras" in mods
    assert not {"xaml3d.render.svg", "xml.sax.saxutils", "urllib.request"} & mods
