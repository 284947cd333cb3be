"""Characters the chosen face lacks: each is set in a font of the system that has it, as WPF
falls back per character (text measured by layout, drawn by the 2D layer).

A face (``xaml3d.fonts``) covers Latin, Greek and Cyrillic; a character it has no glyph for
(Chinese, Arabic, Devanagari...) is drawn in the font the system's fontconfig picks for that
character, through skia's font manager (``matchFamilyStyleCharacter``, with the run's weight and
slant), and measured in it, so a line's width and its drawing agree. A character no installed
font covers keeps the face's empty box; the reader says so once per script (TXT001, naming the
script and the text): ``script_of`` names it.

skia is imported, and fontconfig asked, only for text with a character the face lacks.
"""

from __future__ import annotations

import functools
import os
import sys
import unicodedata

# The scripts by block, for the warning's words (Unicode's block ranges; the first that holds a
# code point names it). Anything else is named by its character name's first word.
_SCRIPTS = (
    (0x0370, 0x03FF, "Greek"), (0x0400, 0x052F, "Cyrillic"), (0x0530, 0x058F, "Armenian"),
    (0x0590, 0x05FF, "Hebrew"), (0x0600, 0x06FF, "Arabic"), (0x0750, 0x077F, "Arabic"),
    (0x0900, 0x097F, "Devanagari"), (0x0980, 0x09FF, "Bengali"), (0x0A00, 0x0A7F, "Gurmukhi"),
    (0x0A80, 0x0AFF, "Gujarati"), (0x0B80, 0x0BFF, "Tamil"), (0x0C00, 0x0C7F, "Telugu"),
    (0x0C80, 0x0CFF, "Kannada"), (0x0D00, 0x0D7F, "Malayalam"), (0x0E00, 0x0E7F, "Thai"),
    (0x0E80, 0x0EFF, "Lao"), (0x0F00, 0x0FFF, "Tibetan"), (0x10A0, 0x10FF, "Georgian"),
    (0x1100, 0x11FF, "Hangul"), (0x1200, 0x139F, "Ethiopic"), (0x1780, 0x17FF, "Khmer"),
    (0x2E80, 0x2FDF, "Han"), (0x3000, 0x303F, "CJK punctuation"), (0x3040, 0x309F, "Hiragana"),
    (0x30A0, 0x30FF, "Katakana"), (0x3130, 0x318F, "Hangul"), (0x3400, 0x4DBF, "Han"),
    (0x4E00, 0x9FFF, "Han"), (0xAC00, 0xD7AF, "Hangul"), (0xE000, 0xF8FF, "private use"),
    (0xF900, 0xFAFF, "Han"), (0xFF00, 0xFFEF, "fullwidth forms"), (0x1F000, 0x1FAFF, "emoji"),
    (0x20000, 0x3FFFF, "Han"), (0xF0000, 0x10FFFF, "private use"),
)  # fmt: skip


def script_of(ch: str) -> str:
    """A name for the script of ``ch`` (Unicode's block, or its name's first word)."""
    cp = ord(ch)
    for lo, hi, name in _SCRIPTS:
        if lo <= cp <= hi:
            return name
    word = unicodedata.name(ch, "").split(" ")[0]
    return word.capitalize() if word else f"U+{cp:04X}"


def needs_glyph(ch: str) -> bool:
    """Whether ``ch`` is drawn (control and format characters are not)."""
    return unicodedata.category(ch) not in ("Cc", "Cf")


@functools.lru_cache(maxsize=1)
def _manager():
    """The system's font manager (fontconfig). Its start-up reads the system's configuration,
    and fontconfig prints its complaints about a configuration newer than skia's own copy of
    it straight to the process's stderr, among the diagnostics: they are dropped here."""
    import skia

    sys.stderr.flush()
    saved = os.dup(2)
    try:
        with open(os.devnull, "wb") as null:
            os.dup2(null.fileno(), 2)
            manager = skia.FontMgr()
            # the first match loads the configuration's fonts, which may complain too
            manager.matchFamilyStyleCharacter("", skia.FontStyle(), [], ord("A"))
    finally:
        os.dup2(saved, 2)
        os.close(saved)
    return manager


def _find(ch: str, weight: int, italic: bool):
    """The system's typeface for ``ch`` at ``weight`` and slant, None where none has it."""
    import skia

    slant = skia.FontStyle.kItalic_Slant if italic else skia.FontStyle.kUpright_Slant
    style = skia.FontStyle(int(weight), skia.FontStyle.kNormal_Width, slant)
    try:
        return _manager().matchFamilyStyleCharacter("", style, [], ord(ch))
    except AttributeError:  # a skia-python without the per-character match: the face's box
        return None


# the finder in use: tests replace it (a system with no font for a script)
finder = _find


@functools.lru_cache(maxsize=4096)
def fallback_typeface(ch: str, weight: int = 400, italic: bool = False):
    """The skia Typeface of the system's font that ``ch`` is set in when the face lacks it,
    None where no installed font has it."""
    return finder(ch, weight, italic)


def runs(text: str, missing, weight: int = 400, italic: bool = False) -> list[tuple[str, object]]:
    """``text`` cut into runs of one font: (text, None) for runs the face sets (including the
    characters no font has: the face's empty box), (text, typeface) for runs a system font
    sets. ``missing``: one bool per character, whether the face lacks it."""
    out: list[tuple[str, object]] = []
    for ch, lacks in zip(text, missing, strict=True):
        tf = fallback_typeface(ch, weight, italic) if lacks and needs_glyph(ch) else None
        if out and out[-1][1] is tf:
            out[-1] = (out[-1][0] + ch, tf)
        else:
            out.append((ch, tf))
    return out


def uncovered(text: str, missing, weight: int = 400, italic: bool = False) -> str:
    """The characters of ``text`` that neither the face (``missing``: one bool per character,
    whether it lacks it) nor any installed font has."""
    return "".join(
        ch
        for ch, lacks in zip(text, missing, strict=True)
        if lacks and needs_glyph(ch) and fallback_typeface(ch, weight, italic) is None
    )
