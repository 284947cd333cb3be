"""LLVM's own messages, kept out of the user's terminal: what LLVM or llvmlite print while the
native loading parses a trampoline's IR, emits or links objects goes to a debug log.

LLVM writes its diagnostics (an IR parser's warnings, a linker's complaints) straight to the C
library's stderr, file descriptor 2, where neither Python's ``sys.stderr`` nor any llvmlite API
can catch them. So around those calls descriptor 2 is pointed at a temporary file and put back
after; whatever landed there is appended to ``<NUMBA_CACHE_DIR>/native/llvm.log`` (kept below
``LOG_LIMIT`` bytes: an older log is started again). The calls take milliseconds; a line another
thread prints in that time goes to the log too, which is why the blocks are kept that short.
"""

from __future__ import annotations

import contextlib
import os
import sys
import tempfile
import threading
from pathlib import Path

LOG_NAME = "llvm.log"
LOG_LIMIT = 1 << 20

_lock = threading.RLock()  # one redirection at a time (a nested block keeps the outer one)
_depth = [0]


def log_path() -> Path:
    """The debug log of the native loading (beside the native objects)."""
    from xaml3d.numba_env import set_cache_dir

    return Path(set_cache_dir()) / "native" / LOG_NAME


@contextlib.contextmanager
def llvm_output():
    """Send what is written to descriptor 2 during the block to the debug log."""
    with _lock:
        if _depth[0]:
            _depth[0] += 1
            try:
                yield
            finally:
                _depth[0] -= 1
            return
        try:
            sys.stderr.flush()  # Python's own buffered text goes where it was meant to
        except (AttributeError, OSError, ValueError):
            pass
        try:
            capture = tempfile.TemporaryFile()
            saved = os.dup(2)
        except OSError:  # no descriptor to spare: LLVM may speak, the work still goes on
            yield
            return
        _depth[0] = 1
        try:
            os.dup2(capture.fileno(), 2)
            try:
                yield
            finally:
                os.dup2(saved, 2)
        finally:
            _depth[0] = 0
            os.close(saved)
            capture.seek(0)
            said = capture.read()
            capture.close()
            if said:
                _append(said)


def _append(data: bytes) -> None:
    try:
        path = log_path()
        path.parent.mkdir(parents=True, exist_ok=True)
        mode = "ab"
        with contextlib.suppress(OSError):
            if path.stat().st_size + len(data) > LOG_LIMIT:
                mode = "wb"
        with open(path, mode) as log:
            log.write(data[-LOG_LIMIT:])
    except (OSError, ImportError):  # a cache folder that cannot be written: the words are lost
        pass
