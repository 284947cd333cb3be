"""Outputs that would overwrite an input: the files the scenes loaded in this process read.

The command line refuses an output that is the scene, a resource dictionary or a texture it
reads (IO002); the Python API does the same. ``xaml3d.load`` notes every file a scene was read
from (``note_read``), so ``save_image``, which gets pixels and knows no scene, can still refuse
to write over one of them; ``export`` also checks its own scene's files.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

_READ: dict[str, str] = {}  # resolved path -> the path as the scene named it


def _resolved(path) -> str:
    try:
        return str(Path(path).resolve())
    except (OSError, RuntimeError, ValueError):
        return os.path.abspath(path)


def note_read(paths: Iterable[str]) -> None:
    """Remember ``paths`` as files a loaded scene reads."""
    for p in paths:
        _READ.setdefault(_resolved(p), str(p))


def _same(a: str, b: str) -> bool:
    if _resolved(a) == _resolved(b):
        return True
    try:  # another spelling of the same file: a hard link, a bind mount
        return os.path.samefile(a, b)
    except (OSError, ValueError):
        return False


def overwritten_input(targets: Iterable, inputs: Iterable = ()) -> tuple[str, str] | None:
    """The first (target, input) pair where writing ``target`` would replace a file that
    ``inputs`` names or that a scene loaded in this process reads; None when there is none."""
    inputs = [str(p) for p in inputs]
    for target in targets:
        target = str(target)
        for p in (*inputs, *_READ.values()):
            if _same(target, p):
                return target, p
    return None


def refusal_message(target: str, source: str) -> str:
    """IO002's message for the API."""
    if _resolved(target) == _resolved(source) and str(target) != str(source):
        return f"{target} is a file the scene reads ({source}): refused"
    return f"{target} is a file the scene reads: refused"
