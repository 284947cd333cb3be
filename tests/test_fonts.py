"""Fonts: the face each FontFamily is set in, its line metrics, characters set in the system's
fonts when the face lacks them, and TXT001 where no installed font has them."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from xaml3d import fonts
from xaml3d.text_metrics import baseline, line_height, text_width, uncovered

HERE = Path(__file__).resolve().parent
CJK_CASE = HERE / "fonts" / "cjk-line.xaml"
CJK_PNG = HERE / "fonts" / "cjk-line.png"
# the CJK font the reference picture of CJK_CASE was drawn with (Debian's fonts-wqy-microhei)
CJK_FAMILY = "WenQuanYi Micro Hei"

WINDOW = """<Grid xmlns="http://schemas.microsoft.com/winfx/2006/xaml/presentation"
    Width="200" Height="40" Background="White">
  <StackPanel>
    {texts}
    <Viewport3D Height="1"/>
  </StackPanel>
</Grid>
"""


@pytest.mark.parametrize(
    ("family", "face"),
    [
        ("Arial", "Liberation Sans"),
        ("Helvetica", "Liberation Sans"),
        ("Times New Roman", "Liberation Serif"),
        ("courier new", "Liberation Mono"),
        ("Consolas", "Liberation Mono"),
        ("Global User Interface", "Liberation Serif"),
        ("./Fonts/#Courier New", "Liberation Mono"),
        ("NoSuchFont, Times New Roman", "Liberation Serif"),
        ("Verdana, Courier New", "Segoe UI"),  # Verdana is on every Windows: it ends the list
        ("Segoe UI", "Segoe UI"),
        ("NoSuchFont", "Segoe UI"),
        ("", "Segoe UI"),
    ],
)
def test_family_chooses_face(family: str, face: str) -> None:
    assert fonts.face_of(family).name == face


def test_line_metrics_are_the_families_as_wpf_reads_them() -> None:
    # WPF's FontFamily.LineSpacing and Baseline of Arial, Times New Roman and Courier New
    # (Windows ascent + descent + the hhea line gap beyond them, in 2048ths of an em)
    assert line_height(10, "Arial") == pytest.approx((1854 + 434 + 67) / 2048 * 10)
    assert baseline(10, "Arial") == pytest.approx(1854 / 2048 * 10)
    assert line_height(10, "Times New Roman") == pytest.approx((1825 + 443 + 87) / 2048 * 10)
    assert baseline(10, "Times New Roman") == pytest.approx(1825 / 2048 * 10)
    assert line_height(10, "Courier New") == pytest.approx((1705 + 615) / 2048 * 10)
    assert baseline(10, "Courier New") == pytest.approx(1705 / 2048 * 10)
    # the default family keeps Segoe UI's
    assert line_height(12) == pytest.approx(15.960937, abs=1e-5)
    assert line_height(12, "Verdana") == line_height(12)


def test_faces_are_metric_compatible() -> None:
    # Courier New: every character 1229/2048 em wide; Arial's and Times New Roman's advances
    # ("H" 1479 and 1479, "i" 455 and 569 in 2048ths)
    assert text_width("iiiii", 12, family="Courier New") == text_width(
        "WWWWW", 12, 700, True, "Courier New"
    )
    assert text_width("i", 2048, family="Courier New") == pytest.approx(1229, abs=0.01)
    assert text_width("H", 2048, family="Arial") == pytest.approx(1479, abs=0.01)
    assert text_width("i", 2048, family="Arial") == pytest.approx(455, abs=0.01)
    assert text_width("i", 2048, family="Times New Roman") == pytest.approx(569, abs=0.01)
    assert text_width("Hello", 12) != text_width("Hello", 12, family="Arial")


def test_bold_and_italic_choose_their_faces() -> None:
    files = {fonts.font_file(w, i, "Arial") for w in (400, 600, 700) for i in (False, True)}
    assert {Path(f).name for f in files} == {
        "LiberationSans-Regular.ttf", "LiberationSans-Bold.ttf",
        "LiberationSans-Italic.ttf", "LiberationSans-BoldItalic.ttf",
    }  # fmt: skip
    assert Path(fonts.font_file(500, False, "Arial")).name == "LiberationSans-Regular.ttf"
    for f in files:
        assert Path(f).is_file()
    assert (Path(fonts.FONT_DIR) / "LICENSE-OFL.txt").is_file()


def _validate(tmp_path: Path, texts: str, *args: str) -> subprocess.CompletedProcess:
    path = tmp_path / "scene.xaml"
    path.write_text(WINDOW.format(texts=texts), encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "xaml3d", "validate", str(path), *args],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip


def test_script_no_font_covers_warns_once(tmp_path: Path) -> None:
    # the Supplementary Private Use Area: no font of any system assigns it a glyph
    texts = (
        '<TextBlock FontFamily="Arial" Text="a &#xF0041;&#xF0042; b"/>'
        '<TextBlock Text="again &#xF0043;"/>'
        '<TextBlock Text="fine: Ελληνικά Кириллица"/>'
    )
    out = _validate(tmp_path, texts)
    warned = [x for x in (out.stdout + out.stderr).splitlines() if "TXT001" in x]
    assert len(warned) == 1, out.stderr
    assert "scene.xaml:4:" in warned[0]
    assert "warning TXT001" in warned[0]
    assert "private use characters" in warned[0]
    assert "U+F0041 U+F0042" in warned[0]
    assert "a \U000f0041\U000f0042 b" in warned[0]
    assert "Traceback" not in out.stderr
    assert out.returncode == 0


def test_per_script_warning_with_no_fallback_font(monkeypatch) -> None:
    """A machine with no font for Chinese (a font manager that finds none): the characters
    keep the face's box, the reader says which script and which text."""
    from xaml3d import font_fallback, load

    monkeypatch.setattr(font_fallback, "finder", lambda ch, weight, italic: None)
    font_fallback.fallback_typeface.cache_clear()
    text_width.cache_clear()
    try:
        assert uncovered("ab中文c", family="Arial") == "中文"
        # the box's advance: the face's .notdef (Liberation Sans: 1536/2048 em)
        assert text_width("中", 2048, family="Arial") == pytest.approx(1536, abs=0.01)
        scene = load(
            WINDOW.format(texts='<TextBlock Text="中文 and Ελληνικά"/><TextBlock Text="字"/>'
                          '<TextBlock Text="&#x0915;"/>'),
            text=True,
        )  # fmt: skip
    finally:
        font_fallback.fallback_typeface.cache_clear()
        text_width.cache_clear()
    warned = [d for d in scene.diagnostics if d.code == "TXT001"]
    assert [d.line for d in warned] == [4, 4]
    assert 'the Han characters of "中文 and Ελληνικά" (U+4E2D U+6587)' in warned[0].message
    assert "the Devanagari characters" in warned[1].message


def _cjk_family() -> str | None:
    from xaml3d import font_fallback

    tf = font_fallback.fallback_typeface("中")
    return None if tf is None else tf.getFamilyName()


def test_chinese_line_falls_back_to_the_systems_font(tmp_path: Path) -> None:
    family = _cjk_family()
    if family is None:
        pytest.skip("no installed font covers Chinese (Debian: fonts-wqy-microhei)")
    from xaml3d import load

    # measured and drawn in the same font: the mixed line is as wide as its pieces
    mixed = text_width("ab中文c", 12, family="Arial")
    assert mixed == pytest.approx(
        text_width("ab", 12, family="Arial") + text_width("中文", 12, family="Arial")
        + text_width("c", 12, family="Arial")
    )  # fmt: skip
    assert text_width("中文", 12, family="Arial") > 2 * 9.0  # wider than two .notdef boxes
    scene = load(CJK_CASE)
    assert not [d for d in scene.diagnostics if d.code == "TXT001"]
    if family != CJK_FAMILY:
        pytest.skip(f"the reference picture is drawn with {CJK_FAMILY}; this system has {family}")
    import numpy as np
    from PIL import Image

    out = tmp_path / "cjk.png"
    done = subprocess.run(
        [sys.executable, "-m", "xaml3d", "render", str(CJK_CASE), "--window", "-o", str(out)],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    got = np.asarray(Image.open(out).convert("RGBA"), dtype=np.int16)
    want = np.asarray(Image.open(CJK_PNG).convert("RGBA"), dtype=np.int16)
    assert got.shape == want.shape
    diff = np.abs(got - want).max(axis=2)
    assert (diff <= 3).mean() >= 0.995 and diff.max() <= 80
