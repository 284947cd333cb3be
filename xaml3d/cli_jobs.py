"""Batches of independent renders in worker processes (``xaml3d render --jobs N``).

Each task runs in a worker of the one pool (``xaml3d.render.workers``) with its stderr
captured; the parent prints every task's captured text in the ORDER OF THE BATCH, so the output
(and every written file) is the same as a serial run's, whatever finishes first.
"""

from __future__ import annotations

import io
import sys
from collections.abc import Callable, Iterator, Sequence

from xaml3d.render.workers import default_jobs, ordered, worker_pool

__all__ = ["default_jobs", "run_ordered"]


def _captured(task: Callable[..., bool], args: tuple) -> tuple[bool, str]:
    """Run ``task(*args)`` with sys.stderr captured: (its result, what it printed)."""
    buffer = io.StringIO()
    saved = sys.stderr
    sys.stderr = buffer
    try:
        ok = task(*args)
    finally:
        sys.stderr = saved
    return ok, buffer.getvalue()


def run_ordered(
    task: Callable[..., bool],
    items: Sequence[tuple],
    jobs: int,
    abandon: Callable[[object], None] | None = None,
    *,
    folders: Sequence[str] = (),
) -> Iterator[tuple[bool, str]]:
    """Yield (result, stderr text) of ``task(*item)`` for every item, in the items' order, with
    up to ``jobs`` worker processes. ``task`` must be a module-level function (picklable).

    Closed early (Ctrl-C, an error in the caller): the items not started are cancelled, the
    running ones finish, and ``abandon(result)`` is called for every result that was computed
    but never yielded (so the caller can remove what it wrote). ``folders``: where the batch
    writes (the workers remove the run's temporaries there should this process be killed)."""
    workers = max(1, min(int(jobs), len(items)))
    with worker_pool(workers, folders=folders) as pool:
        yield from ordered(
            pool,
            _captured,
            [(task, args) for args in items],
            abandon=None if abandon is None else (lambda r: abandon(r[0])),
        )
