"""Layout's text widths from the font's tables (xaml3d.text_advances) are skia's, to the bit."""

from __future__ import annotations

import random

import pytest
import skia

from xaml3d import text_advances as advances
from xaml3d.fonts import font_file, typeface
from xaml3d.text_metrics import text_width

CHARS = [chr(c) for c in range(32, 127)] + list("éàüßñ€–—…“”\t\u00a0\u4e2d\U0001f600\ufffd")
SIZES = [0.05, 0.5, 0.685, 1.0, 6.0, 9.0, 11.0, 12.0, 12.5, 13.333, 13.7, 14.6667, 24.66, 96.0,
         255.9, 256.0, 256.01, 300.0, 342.5, 1000.0, 65536.5]  # fmt: skip


def skia_width(text: str, size: float, weight: int, italic: bool) -> float:
    font = skia.Font(typeface(weight, italic), float(size))
    font.setSubpixel(True)
    font.setHinting(skia.FontHinting.kNone)
    return float(font.measureText(text))


@pytest.mark.parametrize("weight,italic", [(400, False), (700, False), (300, True), (600, True)])
def test_widths_equal_skias_measure_text(weight, italic):
    rng = random.Random(weight + italic)
    path = font_file(weight, italic)
    for size in SIZES:
        for _ in range(40):
            text = "".join(rng.choice(CHARS) for _ in range(rng.randint(1, 40)))
            assert advances.measure(path, text, size) == skia_width(text, size, weight, italic), (
                text,
                size,
            )


def test_a_fine_scan_of_sizes_equals_skia():
    path = font_file(400, False)
    text = "Hello, World! Wg€ 0123"
    for i in range(1, 3000):
        size = i * 0.0917
        assert advances.measure(path, text, size) == skia_width(text, size, 400, False), size


def test_a_size_near_float32s_limit_gives_skias_infinity():
    path = font_file(400, False)
    for size in (1e37, 2e38, 3e38):
        assert advances.measure(path, "Wide", size) == skia_width("Wide", size, 400, False)


def test_known_widths():
    # Open Sans Regular: 'H' advances 1511 units of 2048; at 12 px FreeType's 26.6 size is
    # exact, x_scale = FT_DivFix(768, 2048) = 24576, and FT_MulDiv(1511, 24576, 64) = 580224
    # in 16.16, i.e. 8.853515625 px
    assert advances.measure(font_file(400, False), "H", 12.0) == 8.853515625
    assert advances.measure(font_file(400, False), "HH", 12.0) == 2 * 8.853515625
    assert advances.measure(font_file(400, False), "", 12.0) == 0.0


def test_text_width_uses_the_tables_and_keeps_skia_for_odd_sizes():
    assert text_width("Button", 12.0) == skia_width("Button", 12.0, 400, False)
    assert text_width("Button", 0.0) == skia_width("Button", 0.0, 400, False)
    assert text_width("", 12.0) == 0.0


def test_font_file_is_ttf_opensans_choice():
    import ttf_opensans

    for weight in range(-50, 1100, 7):
        for italic in (False, True):
            chosen = ttf_opensans.opensans(font_weight=weight, italic=italic)
            assert font_file(weight, italic) == str(chosen.path), (weight, italic)
