"""AccessText's rule for a text at rest (Label, Button and the other AccessText hosts, and a
ContentPresenter with RecognizesAccessKey): the access-key marker is not shown."""

from __future__ import annotations


def access_text(text: str) -> str:
    """``text`` as AccessText shows it at rest: the first lone ``_`` (one not doubled, and not
    the last character) is the access-key marker and is not shown; every ``__`` shows one
    ``_``."""
    out, i, marked = [], 0, False
    while i < len(text):
        c = text[i]
        if c == "_" and i + 1 < len(text):
            if text[i + 1] == "_":
                out.append("_")
                i += 2
                continue
            if not marked:
                marked = True
                i += 1
                continue
        out.append(c)
        i += 1
    return "".join(out)
