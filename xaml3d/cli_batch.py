"""``xaml3d render`` of several scenes: where each image goes (``plan``), and a batch in
worker processes whose messages and files come out in batch order, as a serial run's would.

A worker renders a scene with its outputs staged under temporary names (``_Deferred``); the
parent renames them in batch order once it knows that no earlier scene of the batch read those
files, else it renders that scene again itself.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

import click

from xaml3d.cli_common import display_name, io_error
from xaml3d.cli_jobs import run_ordered
from xaml3d.cli_render_scene import (
    FORMATS,
    SUFFIX_FORMATS,
    RenderOptions,
    _Deferred,
    _Failed,
    _render_one,
)
from xaml3d.output.atomic import place


def is_dir_target(output: str) -> bool:
    return output.endswith(("/", os.sep)) or Path(output).is_dir()


def plan(scenes: tuple[str, ...], output: str | None, output_dir: str | None, fmt: str | None):
    """([(scene, target)], output directory or None), target a Path or '-'; raises UsageError
    on an impossible request."""
    if scenes.count("-") > 1:
        raise click.UsageError("stdin ('-') can be read only once")
    if output and output_dir:
        raise click.UsageError("give either -o/--output or --output-dir, not both")
    if output is None and output_dir is None:
        raise click.UsageError(
            "missing the output: -o FILE, -o - (stdout), -o DIR/ or --output-dir DIR"
        )
    directory = output_dir or (output if output != "-" and is_dir_target(output) else None)
    if directory is None:
        if len(scenes) > 1:
            raise click.UsageError(
                "several scenes need an output directory: -o DIR/ or --output-dir DIR"
            )
        if output != "-" and fmt is None and Path(output).suffix.lower() not in SUFFIX_FORMATS:
            raise click.UsageError(
                f"cannot tell the image format of {output!r}: use .png, .jpg, .webp, .svg or "
                "--format"
            )
        return [(scenes[0], output if output == "-" else Path(output))], None
    suffix = FORMATS[fmt or "png"]
    stem = {s: Path(s).stem if s != "-" else "stdin" for s in scenes}
    return [(s, Path(directory) / (stem[s] + suffix)) for s in scenes], Path(directory)


def _render_task(source: str, target, opts: RenderOptions, inputs: list[Path]):
    """One scene of a parallel batch (in a worker process): (rendered, its outputs as
    (temporary path, target) pairs, the files it read)."""
    _Deferred.active = deferred = _Deferred()
    try:
        _render_one(source, target, opts, inputs)
        ok = True
    except _Failed:
        ok = False
    finally:
        _Deferred.active = None
    return ok, deferred.pending, deferred.read


def _place_all(pending, name: str) -> bool:
    """Put a scene's finished temporaries in place (``atomic.place``: renamed, or copied into a
    FIFO or device); False, with the RND007 line a serial run prints, when one cannot be."""
    for i, (tmp, out) in enumerate(pending):
        try:
            place(tmp, out)
        except OSError as exc:
            _discard(pending[i + 1 :])
            msg = f"cannot write {out}: {exc.strerror or exc}"
            click.echo(io_error(name, msg, "RND007"), err=True)
            return False
    return True


def _discard(pending) -> None:
    for tmp, _ in pending:
        try:
            os.unlink(tmp)
        except OSError:
            pass


def parallel_steps(plan, opts, inputs, jobs, written: set, failed: list):
    """Steps that print each scene's messages in batch order while worker processes render; None
    when a serial run is as good (one scene, or stdin, which only this process can read)."""
    if len(plan) < 2 or any(source == "-" for source, _ in plan):
        return None
    todo, items = [], []
    for source, target in plan:  # the serial run's duplicate-output check, in the same order
        key = Path(os.path.abspath(target))
        duplicate = key in written
        written.add(key)
        todo.append((source, target, duplicate))
        if not duplicate:
            items.append((source, target, opts, inputs))
    # Interrupted: the finished scenes' temporaries are removed, never renamed into place.
    folders = sorted({str(Path(target).parent) for _, target in plan})
    results = run_ordered(
        _render_task, items, jobs, abandon=lambda r: _discard(r[1]), folders=folders
    )
    read_before: list[Path] = []  # what the earlier scenes of the batch read
    made: set[str] = set()  # what the earlier scenes of the batch wrote

    def step(source: str, target, duplicate: bool) -> None:
        if duplicate:
            msg = f"{target} is already the output of another scene of this batch"
            click.echo(io_error(display_name(source), msg, "IO003"), err=True)
            failed.append(display_name(source))
            return
        (ok, pending, read), text = next(results)
        earlier = {os.path.abspath(p) for p in read_before}
        clash = any(os.path.abspath(out) in earlier for _, out in pending)
        if clash or made.intersection(read):
            # It would write over a file an earlier scene read, or it read a file an earlier
            # scene wrote: what a serial run does depends on that order, so do it serially.
            _discard(pending)
            ok, pending, read = _render_task(source, target, opts, [*inputs, *read_before])
        else:
            sys.stderr.write(text)
            sys.stderr.flush()
        ok = _place_all(pending, display_name(source)) and ok
        read_before.extend(Path(p) for p in read)
        made.update(os.path.abspath(out) for _, out in pending)
        if not ok:
            failed.append(display_name(source))

    batch = Batch(lambda args=args: step(*args) for args in todo)
    batch.close = results.close
    return batch


class Batch(list):
    """The steps of a parallel batch; ``close()`` stops its workers when the batch ends early
    (Ctrl-C): queued scenes are cancelled and finished ones' temporaries removed."""

    def close(self) -> None:  # replaced by the batch's own
        pass
