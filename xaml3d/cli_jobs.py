"""Batches of independent renders in worker processes (``xaml3d render --jobs N``).

Each task runs in a worker with its stderr captured; the parent prints every task's captured text
in the ORDER OF THE BATCH, so the output (and every written file) is the same as a serial run's,
whatever finishes first. Workers are forked where the platform allows it (they start with the
parent's modules already imported), else spawned.
"""

from __future__ import annotations

import io
import os
import sys
from collections.abc import Callable, Iterator, Sequence


def default_jobs() -> int:
    """The number of cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


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


def _ignore_interrupt() -> None:
    import signal

    # Ctrl-C reaches the whole process group: the parent stops the batch (run_ordered), a
    # worker just finishes its scene instead of printing a traceback of its own.
    signal.signal(signal.SIGINT, signal.SIG_IGN)


def run_ordered(
    task: Callable[..., bool],
    items: Sequence[tuple],
    jobs: int,
    abandon: Callable[[object], None] | None = None,
) -> Iterator[tuple[bool, str]]:
    """Yield (result, stderr text) of ``task(*item)`` for every item, in the items' order, with
    up to ``jobs`` worker processes. ``task`` must be a module-level function (picklable).

    Closed early (Ctrl-C, an error in the caller): the items not started are cancelled, the
    running ones finish, and ``abandon(result)`` is called for every result that was computed
    but never yielded (so the caller can remove what it wrote)."""
    # Imported here: a single render (the common, small case) never pays for them.
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    workers = max(1, min(int(jobs), len(items)))
    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    futures: list = []
    given = 0
    try:
        with ProcessPoolExecutor(
            max_workers=workers, mp_context=ctx, initializer=_ignore_interrupt
        ) as pool:
            futures = [pool.submit(_captured, task, args) for args in items]
            try:
                for future in futures:
                    result = future.result()
                    given += 1
                    yield result
            finally:
                for future in futures:
                    future.cancel()  # leaving the pool then waits for the running ones only
    finally:
        for future in futures[given:]:
            if abandon is not None and future.done() and not future.cancelled():
                if future.exception() is None:
                    abandon(future.result()[0])
