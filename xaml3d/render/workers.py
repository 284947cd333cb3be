"""The one worker pool: independent renders (frames of an animation, scenes of a batch) in
worker processes, results in submission order.

``worker_pool(n)`` is a ``ProcessPoolExecutor`` whose workers are forked where the platform
allows it (they start with the parent's modules and loaded scene already there), else spawned;
ignore Ctrl-C (it reaches the whole process group: the parent stops the run, a worker just
finishes its task instead of printing a traceback of its own); and die with their parent even
when it is killed outright (SIGKILL runs no handler): on Linux the kernel sends each worker
SIGTERM when the parent dies (``prctl(PR_SET_PDEATHSIG)``), elsewhere a thread of each worker
notices that its parent process changed (``os.getppid``, checked every half second). A worker
leaving so first removes the temporary files its own writes left (``xaml3d.output.atomic``)
and those its parent was writing (named with the parent's process id), so a killed run leaves
neither workers nor temporaries.

``ordered(executor, fn, items)`` runs ``fn(*item)`` for every item on ANY
``concurrent.futures.Executor`` and yields the results in the items' order, with at most a few
per worker in flight: a long animation streams through, never all held in memory. Closed early
(Ctrl-C, an error in the caller), the items not started are cancelled, and ``abandon(result)``
is called for every result that was computed but never yielded.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from typing import TYPE_CHECKING

from xaml3d.output import atomic

if TYPE_CHECKING:
    from concurrent.futures import Executor, ProcessPoolExecutor

PR_SET_PDEATHSIG = 1  # linux/prctl.h
PF_EXITING = 0x4  # linux/sched.h: the task has begun to exit
IN_FLIGHT_PER_WORKER = 2  # tasks queued per worker: it never waits, the parent holds little


def default_jobs() -> int:
    """The number of cores this process may run on."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


_PARENT: tuple[int, tuple[str, ...]] | None = None  # a worker's (parent pid, its folders)


def _orphaned() -> bool:
    """Whether the parent is dead or dying. ``os.getppid`` changes only once the worker has
    been handed to a new parent, a little after the parent's files (the task pipe) close and
    its death signal is sent; on Linux the parent's own flags say at once that it is exiting."""
    if _PARENT is None:
        return False
    if os.getppid() != _PARENT[0]:
        return True
    try:
        with open(f"/proc/{_PARENT[0]}/stat", "rb") as fh:
            fields = fh.read().rsplit(b")", 1)[1].split()
    except OSError:
        return os.path.isdir("/proc/self")  # gone; without /proc only getppid can tell
    return fields[0] in (b"Z", b"X") or bool(int(fields[6]) & PF_EXITING)


def _clean_if_orphaned() -> None:
    """The parent is gone (not a pool's own shutdown): remove the temporaries of the run."""
    if _orphaned():
        atomic.remove_temporaries(os.getpid())
        atomic.remove_temporaries(_PARENT[0], _PARENT[1])


def _leave(*_args) -> None:
    """SIGTERM (the parent's death signal, or a broken pool torn down): remove this worker's
    temporaries, and the parent's when it is gone, then exit at once."""
    atomic.remove_temporaries(os.getpid())
    _clean_if_orphaned()
    os._exit(1)


def _watch(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(0.5)
    _leave()


def _start_worker(parent: int, folders, initializer, initargs) -> None:
    global _PARENT
    _PARENT = (parent, tuple(folders))
    # The parent's death also closes the pipe the worker reads its tasks from: a worker that
    # sees that first ends with an error before the signal arrives, and cleans up on its way out
    from multiprocessing import util

    util.Finalize(None, _clean_if_orphaned, exitpriority=100)
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, _leave)
    watched = False
    if sys.platform.startswith("linux"):
        import ctypes  # in a worker only, and only where prctl exists

        try:
            libc = ctypes.CDLL(None, use_errno=True)
            watched = libc.prctl(PR_SET_PDEATHSIG, signal.SIGTERM, 0, 0, 0) == 0
        except (OSError, AttributeError):
            pass
    if not watched:
        threading.Thread(target=_watch, args=(parent,), daemon=True).start()
    if os.getppid() != parent:  # the parent died before the watch began
        _leave()
    if initializer is not None:
        initializer(*initargs)


def worker_pool(
    workers: int,
    initializer: Callable | None = None,
    initargs: tuple = (),
    *,
    folders: Sequence[str] = (),
) -> ProcessPoolExecutor:
    """A pool of ``workers`` processes (module docstring); ``initializer(*initargs)`` runs in
    each. ``folders``: where the parent writes temporaries during the run (they are removed
    by the workers should the parent be killed)."""
    # Imported here: a single render (the common, small case) never pays for them.
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    return ProcessPoolExecutor(
        max_workers=max(1, int(workers)),
        mp_context=ctx,
        initializer=_start_worker,
        initargs=(os.getpid(), tuple(str(f) for f in folders), initializer, initargs),
    )


def ordered(
    executor: Executor,
    fn: Callable,
    items: Sequence[tuple],
    *,
    abandon: Callable[[object], None] | None = None,
    window: int | None = None,
) -> Iterator:
    """Yield ``fn(*item)`` for every item, in the items' order, computed on ``executor``
    (module docstring). ``window``: tasks in flight (default: a few per worker of a process
    pool, else 8)."""
    if window is None:
        workers = getattr(executor, "_max_workers", 4) or 4
        window = max(2, IN_FLIGHT_PER_WORKER * int(workers))
    queue: deque = deque()
    todo = iter(items)
    try:
        for item in todo:
            queue.append(executor.submit(fn, *item))
            if len(queue) >= window:
                break
        while queue:
            result = queue.popleft().result()
            for item in todo:  # keep the window full: one in, one out
                queue.append(executor.submit(fn, *item))
                break
            yield result
    finally:
        for future in queue:
            future.cancel()  # the running ones finish; leaving the pool waits for them only
        for future in queue:
            if abandon is not None and not future.cancelled():
                try:
                    result = future.result()
                except Exception:  # a failed task left nothing to remove
                    continue
                abandon(result)
