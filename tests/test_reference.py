"""The reference-image suite: every ``tests/reference/<area>/<case>.xaml`` against its ``.png``.

What each case must look like is written in ``tests/reference/CASES.md`` (and repeated in a
comment at the top of each case file); the PNGs are renders that were checked by eye against
those words.

Comparison (per pixel, per RGBA channel, 8-bit straight alpha, both images the same size):

- at least ``STRICT_FRACTION`` (99.5%) of the pixels differ by at most ``STRICT_DIFF`` (3) on
  every channel: rounding noise is tolerated, a changed region is not;
- no pixel differs by more than ``MAX_DIFF`` (80) on any channel: with the default 2x2
  supersampling one flipped sub-sample at an edge moves a channel by at most 255/4 ~= 64, so a
  single edge pixel may wobble, but a wrong colour anywhere (even one pixel) fails.

On failure a side-by-side picture ``expected | actual | diff x8`` (transparent areas shown over a
grey checkerboard) is written to ``tests/reference/_failures/<area>__<case>.png`` and the test
fails with its path. Cases named ``window-*`` are ``render --window`` pictures (the root's whole
client area, every viewport at its layout rectangle) in the ``layout`` area; the others render
the first viewport.

Regenerating the expected PNGs from the current renderer::

    XAML3D_REGENERATE=1 pytest tests/test_reference.py -k "camera"

writes (overwrites) ``<case>.png`` for every selected case and STILL FAILS each one
("regenerated, check by eye and re-run"): look at every new PNG against CASES.md, then run again
without the variable. A case without a PNG fails with the same advice; it never passes or skips
silently. Cases listed in ``tests/reference/KNOWN_GAPS.md`` are ``xfail(strict=True)``.

Only files exactly one folder deep are cases; deeper files (textures, merged dictionaries) and
folders starting with ``_`` or ``.`` are not.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from lxml import etree
from PIL import Image

ROOT = Path(__file__).resolve().parent.parent
REFERENCE = Path(__file__).resolve().parent / "reference"
FAILURES = REFERENCE / "_failures"
GAPS_FILE = REFERENCE / "KNOWN_GAPS.md"
CASES_FILE = REFERENCE / "CASES.md"
SAMPLES = ROOT / "samples"

STRICT_DIFF = 3
STRICT_FRACTION = 0.995
MAX_DIFF = 80
DIFF_GAIN = 8

PRESENTATION = "http://schemas.microsoft.com/winfx/2006/xaml/presentation"
XAML_LANGUAGE = "http://schemas.microsoft.com/winfx/2006/xaml"
REGENERATE_ENV = "XAML3D_REGENERATE"

_CASE_NAME = re.compile(r"^[a-z0-9-]+/[a-z0-9-]+$")


# --------------------------------------------------------------------------- harness helpers


def discover_cases(root: Path = REFERENCE) -> list[Path]:
    """Case files: ``root/<area>/<case>.xaml``, areas not starting with ``_`` or ``.``."""
    return sorted(p for p in root.glob("*/*.xaml") if not p.parent.name.startswith(("_", ".")))


def case_id(path: Path, root: Path = REFERENCE) -> str:
    """``area/case`` for a case file (the pytest id and the key in CASES.md / KNOWN_GAPS.md)."""
    rel = path.relative_to(root)
    return f"{rel.parent.as_posix()}/{rel.stem}"


def parse_known_gaps(text: str) -> dict[str, str]:
    """Rows of the markdown table ``| case | reason |`` -> {case: reason}.

    The header row, the ``|---|`` separator and anything outside the table are ignored; the case
    may be wrapped in backticks. A row whose first cell is not ``area/case`` is an error, so a
    typo cannot silently disable a gap.
    """
    gaps: dict[str, str] = {}
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = line.strip()
        if not stripped.startswith("|"):
            continue
        cells = [c.strip() for c in stripped.strip("|").split("|")]
        first = cells[0].strip("`").strip()
        if first.lower() == "case" or set(first) <= set("-: "):
            continue
        if not _CASE_NAME.match(first):
            raise ValueError(f"KNOWN_GAPS.md line {number}: {first!r} is not area/case")
        reason = " | ".join(cells[1:]).strip() if len(cells) > 1 else ""
        gaps[first] = reason or "known gap (no reason given)"
    return gaps


def regenerate_requested(environ: dict[str, str] | None = None) -> bool:
    """True when XAML3D_REGENERATE is set to anything but empty, 0, false or no."""
    value = (os.environ if environ is None else environ).get(REGENERATE_ENV, "")
    return value.strip().lower() not in ("", "0", "false", "no")


@dataclass(frozen=True)
class Comparison:
    ok: bool
    reason: str
    within_fraction: float  # share of pixels within STRICT_DIFF on every channel
    max_diff: int


def _rgba_array(img: Image.Image) -> np.ndarray:
    return np.asarray(img.convert("RGBA"), dtype=np.int16)


def compare_images(
    expected: Image.Image,
    actual: Image.Image,
    strict_diff: int = STRICT_DIFF,
    strict_fraction: float = STRICT_FRACTION,
    max_diff: int = MAX_DIFF,
) -> Comparison:
    """Per-channel RGBA comparison with the suite's tolerance (see the module docstring)."""
    if expected.size != actual.size:
        return Comparison(
            False, f"size differs: expected {expected.size}, got {actual.size}", 0.0, 255
        )
    diff = np.abs(_rgba_array(expected) - _rgba_array(actual)).max(axis=2)
    worst = int(diff.max()) if diff.size else 0
    within = float((diff <= strict_diff).mean()) if diff.size else 1.0
    problems = []
    if within < strict_fraction:
        problems.append(
            f"only {within:.2%} of pixels within {strict_diff} (need {strict_fraction:.1%})"
        )
    if worst > max_diff:
        bad = int((diff > max_diff).sum())
        problems.append(f"{bad} pixel(s) differ by more than {max_diff} (worst {worst})")
    return Comparison(not problems, "; ".join(problems) or "match", within, worst)


def _over_checkerboard(img: Image.Image, cell: int = 4) -> Image.Image:
    """Composite RGBA over a light/dark grey checkerboard so transparency is visible."""
    w, h = img.size
    ys, xs = np.mgrid[0:h, 0:w]
    board = np.where(((xs // cell + ys // cell) % 2)[..., None] == 0, 200, 150)
    back = Image.fromarray(np.repeat(board, 3, axis=2).astype(np.uint8), "RGB").convert("RGBA")
    return Image.alpha_composite(back, img.convert("RGBA")).convert("RGB")


def diff_image(expected: Image.Image, actual: Image.Image, gain: int = DIFF_GAIN) -> Image.Image:
    """``expected | actual | diff`` side by side; diff = max channel difference x gain, grey."""
    w = max(expected.width, actual.width)
    h = max(expected.height, actual.height)
    sheet = Image.new("RGB", (3 * w, h), (255, 0, 255))  # magenta marks size mismatch padding
    sheet.paste(_over_checkerboard(expected), (0, 0))
    sheet.paste(_over_checkerboard(actual), (w, 0))
    if expected.size == actual.size:
        diff = np.abs(_rgba_array(expected) - _rgba_array(actual)).max(axis=2)
        amplified = np.clip(diff * gain, 0, 255).astype(np.uint8)
        sheet.paste(Image.fromarray(amplified, "L").convert("RGB"), (2 * w, 0))
    return sheet


def write_failure(
    case: str, expected: Image.Image, actual: Image.Image, folder: Path = FAILURES
) -> Path:
    """Write the side-by-side failure picture for ``area/case``; return its path."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / (case.replace("/", "__") + ".png")
    diff_image(expected, actual).save(path)
    return path


# --------------------------------------------------------------------------- the suite


def _case_params() -> list:
    regenerate = regenerate_requested()
    gaps = {} if regenerate else parse_known_gaps(GAPS_FILE.read_text(encoding="utf-8"))
    params = []
    for path in discover_cases():
        cid = case_id(path)
        marks = [pytest.mark.xfail(strict=True, reason=gaps[cid])] if cid in gaps else []
        params.append(pytest.param(path, id=cid, marks=marks))
    return params


def _picture(path: Path, t: float) -> Image.Image:
    """The case drawn at ``t``: one viewport, or for ``layout/window-*`` cases the whole client
    area as ``render --window`` draws it."""
    import xaml3d

    if path.parent.name == "layout" and path.stem.startswith("window-"):
        from xaml3d.pipeline import load
        from xaml3d.render.window import compose_window

        rgba, _ = compose_window(load(path), time=t)
        return Image.fromarray(rgba, mode="RGBA")
    return xaml3d.render(str(path), time=t).convert("RGBA")


_TIMES = re.compile(r"TIMES:((?:\s+[0-9.]+)+)")


def case_times(path: Path) -> list[float]:
    """Extra moments an animated case is drawn at: ``TIMES: 0.5 1`` in its top comment; each
    has its own expected image ``<case>@<t>s.png`` beside the default (t = 0) ``<case>.png``."""
    m = _TIMES.search(path.read_text(encoding="utf-8")[:2000])
    return [float(x) for x in m.group(1).split()] if m else []


def time_png(path: Path, t: float) -> Path:
    return path.with_name(f"{path.stem}@{t:g}s.png")


@pytest.mark.parametrize("case_path", _case_params())
@pytest.mark.parametrize("kernels", ["numpy", "numba"])
def test_reference_case(case_path: Path, kernels: str, monkeypatch) -> None:
    """Every case on both renderer paths: numpy, and the compiled kernels (tests/test_kernels.py
    checks that the two give bit-identical pictures)."""

    monkeypatch.setenv("XAML3D_KERNELS", kernels)
    cid = case_id(case_path)
    shots = [(case_path.with_suffix(".png"), cid, 0.0)]
    shots += [(time_png(case_path, t), f"{cid}@{t:g}s", t) for t in case_times(case_path)]
    for expected_png, sid, t in shots:
        actual = _picture(case_path, t)
        if regenerate_requested():
            actual.save(expected_png)
            continue
        if not expected_png.exists():
            pytest.fail(
                f"{sid}: no expected image {expected_png.relative_to(ROOT)}; generate it with "
                f'{REGENERATE_ENV}=1 pytest tests/test_reference.py -k "{cid}", check it by eye '
                "against tests/reference/CASES.md, then re-run"
            )
        with Image.open(expected_png) as img:
            expected = img.convert("RGBA")
        result = compare_images(expected, actual)
        if not result.ok:
            sheet = write_failure(sid.replace("@", "_at_"), expected, actual)
            pytest.fail(f"{sid}: {result.reason}; expected | actual | diff: {sheet}")
    if regenerate_requested():
        pytest.fail(
            f"{cid}: regenerated {len(shots)} image(s), check them by eye against "
            f"tests/reference/CASES.md and re-run without {REGENERATE_ENV}"
        )


def _all_xaml() -> list:
    files = sorted(REFERENCE.rglob("*.xaml")) + sorted(SAMPLES.rglob("*.xaml"))
    return [
        pytest.param(p, id=p.relative_to(ROOT).as_posix())
        for p in files
        if "_failures" not in p.parts
    ]


ROOTS = {"Window", "Page", "Grid", "Viewport3D", "UserControl", "ResourceDictionary"}


@pytest.mark.parametrize("path", _all_xaml())
def test_reference_cases_are_wellformed(path: Path) -> None:
    """Every case, helper and sample parses, uses the WPF namespaces and starts with a comment."""
    parser = etree.XMLParser(resolve_entities=False, no_network=True)
    tree = etree.parse(str(path), parser)
    root = tree.getroot()
    qname = etree.QName(root)
    assert qname.namespace == PRESENTATION, f"{path}: root namespace {qname.namespace}"
    assert qname.localname in ROOTS, f"{path}: unexpected root <{qname.localname}>"
    assert root.nsmap.get("x") == XAML_LANGUAGE, f"{path}: xmlns:x missing or wrong"
    first = root.getprevious()
    while first is not None and first.getprevious() is not None:
        first = first.getprevious()
    assert isinstance(first, etree._Comment), f"{path}: needs a comment saying what it shows"
    viewports = root.iter(f"{{{PRESENTATION}}}Viewport3D")
    if qname.localname != "ResourceDictionary":
        assert next(viewports, None) is not None, f"{path}: no Viewport3D"


def test_every_case_is_described_in_cases_md() -> None:
    listed = re.findall(r"^- `([^`]+)`:", CASES_FILE.read_text(encoding="utf-8"), re.M)
    cases = [case_id(p) for p in discover_cases()]
    assert len(cases) >= 80
    assert sorted(listed) == sorted(cases)
    assert len(set(listed)) == len(listed)


def test_repository_known_gaps_name_real_cases() -> None:
    gaps = parse_known_gaps(GAPS_FILE.read_text(encoding="utf-8"))
    cases = {case_id(p) for p in discover_cases()}
    assert set(gaps) <= cases, sorted(set(gaps) - cases)


# --------------------------------------------------------------------------- harness self-tests


def _solid(w: int, h: int, rgba: tuple[int, int, int, int]) -> Image.Image:
    return Image.new("RGBA", (w, h), rgba)


def test_compare_identical_and_rounding_noise() -> None:
    a = _solid(20, 20, (10, 200, 30, 255))
    assert compare_images(a, a.copy()).ok
    # 3 off on every channel of every pixel is noise: 100% of pixels within 3, worst 3.
    b = _solid(20, 20, (13, 197, 33, 252))
    r = compare_images(a, b)
    assert r.ok and r.max_diff == 3 and r.within_fraction == 1.0


def test_compare_fraction_threshold() -> None:
    a = _solid(20, 20, (0, 0, 0, 255))  # 400 pixels; 99.5% of 400 = 398 must be within 3
    two_off = a.copy()
    two_off.putpixel((0, 0), (0, 50, 0, 255))
    two_off.putpixel((1, 0), (0, 50, 0, 255))
    r = compare_images(a, two_off)
    assert r.ok and r.within_fraction == pytest.approx(398 / 400)
    three_off = two_off.copy()
    three_off.putpixel((2, 0), (0, 4, 0, 255))  # just over 3
    r = compare_images(a, three_off)
    assert not r.ok and r.within_fraction == pytest.approx(397 / 400)
    assert "99.25%" in r.reason


def test_compare_single_pixel_over_max_fails() -> None:
    a = _solid(40, 40, (0, 0, 0, 255))  # 1600 pixels: one pixel is 0.06%, fraction still fine
    edge = a.copy()
    edge.putpixel((5, 5), (MAX_DIFF, 0, 0, 255))
    assert compare_images(a, edge).ok  # 80 is allowed (an edge sub-sample flip)
    red = a.copy()
    red.putpixel((5, 5), (255, 0, 0, 255))
    r = compare_images(a, red)
    assert not r.ok and r.max_diff == 255 and "1 pixel(s)" in r.reason


def test_compare_alpha_counts_and_size_mismatch() -> None:
    opaque = _solid(10, 10, (0, 255, 0, 255))
    clear = _solid(10, 10, (0, 255, 0, 0))
    assert not compare_images(opaque, clear).ok
    r = compare_images(opaque, _solid(10, 12, (0, 255, 0, 255)))
    assert not r.ok and "(10, 10)" in r.reason and "(10, 12)" in r.reason


def test_diff_image_layout_and_amplification(tmp_path: Path) -> None:
    expected = _solid(8, 6, (0, 0, 255, 255))
    actual = expected.copy()
    actual.putpixel((3, 2), (0, 0, 245, 255))  # 10 off -> 80 in the x8 diff panel
    sheet = diff_image(expected, actual)
    assert sheet.size == (24, 6)
    assert sheet.getpixel((3, 2)) == (0, 0, 255)  # expected panel, opaque so no checkerboard
    assert sheet.getpixel((8 + 3, 2)) == (0, 0, 245)  # actual panel
    assert sheet.getpixel((16 + 3, 2)) == (80, 80, 80)  # 10 * 8
    assert sheet.getpixel((16 + 0, 0)) == (0, 0, 0)
    path = write_failure("camera/fov-90", expected, actual, tmp_path / "_failures")
    assert path == tmp_path / "_failures" / "camera__fov-90.png"
    with Image.open(path) as img:
        assert img.size == (24, 6)


def test_diff_image_shows_transparency_and_size_mismatch() -> None:
    clear = _solid(8, 8, (0, 0, 0, 0))
    sheet = diff_image(clear, _solid(4, 4, (0, 255, 0, 255)))
    assert sheet.size == (24, 8)
    assert sheet.getpixel((0, 0)) == (200, 200, 200)  # checkerboard light cell
    assert sheet.getpixel((4, 0)) == (150, 150, 150)  # next cell is dark
    assert sheet.getpixel((8 + 6, 6)) == (255, 0, 255)  # padding around the smaller image


def test_parse_known_gaps() -> None:
    text = (
        "# gaps\n\nsome prose | with a bar\n\n| case | reason |\n|------|--------|\n"
        "| `light/spot-between-cones` | cone falloff not yet per vertex |\n"
        "| brush/radial-gradient-origin | focal point | approximated |\n"
    )
    assert parse_known_gaps(text) == {
        "light/spot-between-cones": "cone falloff not yet per vertex",
        "brush/radial-gradient-origin": "focal point | approximated",
    }
    assert parse_known_gaps("| case | reason |\n|---|---|\n") == {}
    with pytest.raises(ValueError, match="line 3"):
        parse_known_gaps("| case | reason |\n|---|---|\n| spot between | typo |\n")


def test_regenerate_flag() -> None:
    assert not regenerate_requested({})
    assert not regenerate_requested({REGENERATE_ENV: "0"})
    assert not regenerate_requested({REGENERATE_ENV: "false"})
    assert regenerate_requested({REGENERATE_ENV: "1"})
    assert regenerate_requested({REGENERATE_ENV: "yes"})


def test_discover_cases_skips_helpers(tmp_path: Path) -> None:
    for rel in ("camera/a.xaml", "camera/deep/helper.xaml", "_failures/x.xaml", "top.xaml"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text("<x/>")
    found = [case_id(p, tmp_path) for p in discover_cases(tmp_path)]
    assert found == ["camera/a"]
