"""The files ``xaml3d animate`` writes: which they are, and what must never happen to them.

- The output is told from ``-o`` before the scene is read (a usage error, exit 2, as ``render``
  does for a suffix it cannot write): ``.gif``, ``.png``/``.apng`` (APNG), ``.webp``, or a
  directory (``DIR/`` or an existing one) for ``frame_0000.png`` ...
- No output may be a file the scene reads (the scene, ``-r`` dictionaries, App.xaml, ImageBrush
  images): ``overwritten_input`` finds the first such pair among every path the command would
  write (each frame file of a sequence), so the command refuses (IO002) before writing anything.
- A directory sequence is written frame by frame as the frames are drawn (``FrameSequence``:
  memory for one frame, however long the animation), under temporary names renamed into place
  once every frame is drawn: a failure or Ctrl-C leaves no new frame file.
- A sequence written into a directory that holds frame files of an earlier, longer run would be
  seen mixed with them: ``stale_frames`` lists them (warning IO004), ``--clean`` removes them
  (only files named like frames, never a file the scene reads).
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

import click

from xaml3d.cli_common import _resolved, same_file
from xaml3d.codes.outputs import OUTPUT_CODES  # noqa: F401 (the stage's table)
from xaml3d.output.animation import ANIMATED_FORMATS, FRAME_FILE
from xaml3d.output.atomic import Staged, together, write_atomically
from xaml3d.output.images import save_image


def animation_target(output: str) -> bool:
    """Check ``-o`` of ``animate`` before anything is read: True for a directory sequence,
    False for an animated file. Raises click.UsageError (exit 2) for what cannot be written."""
    if output == "-":
        raise click.UsageError(
            "animate writes files, not stdout: use -o FILE.gif|.png|.webp or -o DIR/"
        )
    if output.endswith(("/", os.sep)) or Path(output).is_dir():
        return True
    if Path(output).suffix.lower() not in ANIMATED_FORMATS:
        raise click.UsageError(
            f"cannot tell the animation format of {output!r}: use .gif, .png (APNG), .webp, "
            "or DIR/ for numbered PNG frames"
        )
    return False


def overwritten_input(outputs: Iterable[Path], inputs: Iterable[Path]) -> tuple[Path, Path] | None:
    """The first (output, input) pair where writing the output would replace the input, as
    ``cli_common.same_file`` decides; None when there is none. Quick for thousands of frame
    files: a missing output is compared by its resolved folder and name only."""
    inputs = list(inputs)
    by_path = {}
    for p in inputs:
        by_path.setdefault(_resolved(p), p)
    existing = [p for p in inputs if p.exists()]
    folders: dict[Path, Path] = {}
    for out in outputs:
        if out.exists():  # possibly a link or another spelling of an input
            for p in existing:
                if same_file(out, p):
                    return out, p
            continue
        folder = folders.setdefault(out.parent, _resolved(out.parent))
        hit = by_path.get(folder / out.name)
        if hit is not None:
            return out, hit
    return None


def stale_frames(directory: Path, written: Iterable[str]) -> list[Path]:
    """Files of ``directory`` named like frames (``frame_0000.png``...) that a sequence of the
    ``written`` names leaves in place, in name order."""
    keep = set(written)
    try:
        names = sorted(e.name for e in os.scandir(directory) if e.is_file())
    except OSError:  # no directory yet: nothing stale
        return []
    return [directory / n for n in names if FRAME_FILE.fullmatch(n) and n not in keep]


def remove_stale(stale: list[Path], inputs: list[Path]) -> list[Path]:
    """Delete the stale frame files that are not read by the scene; return those left."""
    left = []
    for path in stale:
        if any(same_file(path, p) for p in inputs):
            left.append(path)
            continue
        try:
            path.unlink()
        except FileNotFoundError:
            pass
        except OSError:
            left.append(path)
    return left


def stale_message(directory: str, stale: list[Path], count: int, clean: bool) -> str:
    """The IO004 message for ``stale`` frame files left beside ``count`` new frames."""
    span = stale[0].name if len(stale) == 1 else f"{stale[0].name} .. {stale[-1].name}"
    head = f"{directory} still holds {len(stale)} frame file(s) of an earlier run ({span})"
    if clean:
        return f"{head} that --clean cannot remove (read by the scene, or not deletable)"
    return (
        f"{head} beside the {count} written: a viewer of the sequence shows them too "
        "(--clean removes them)"
    )


class FrameSequence:
    """The frame files of ``directory``, written as the frames come under hidden temporary
    names (never named like frames): ``commit`` renames them all into place, ``discard`` (a
    no-op after ``commit``) removes what was written."""

    def __init__(self, directory: Path, names: list[str]) -> None:
        self.directory = directory
        self.names = names
        self.written: list[tuple[Path, Path]] = []  # (temporary, final)
        directory.mkdir(parents=True, exist_ok=True)

    def add(self, frame) -> None:
        """The next frame: an RGBA array, or its PNG file's bytes (``images.png_bytes``,
        encoded where it was drawn)."""
        final = self.directory / self.names[len(self.written)]
        with together(commit=False) as staged:  # a temporary name, renamed by ``commit``
            if isinstance(frame, bytes):
                write_atomically(final, lambda fh: fh.write(frame))
            else:
                save_image(frame, final, format="PNG")
        self.written.extend(staged.pending)

    def commit(self) -> None:
        staged = Staged()
        staged.pending, self.written = self.written, []
        staged.commit()

    def discard(self) -> None:
        staged = Staged()
        staged.pending, self.written = self.written, []
        staged.discard()
