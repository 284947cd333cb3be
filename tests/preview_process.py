"""A ``xaml3d preview`` process for the tests: started on a file, its URL read from its first
line (bounded wait), its state polled over HTTP, always stopped (SIGINT, then kill)."""

from __future__ import annotations

import json
import os
import queue
import signal
import subprocess
import sys
import threading
import time
import urllib.request
from pathlib import Path

STARTUP = 120.0  # seconds: the first render on a busy machine
CHANGE = 30.0  # seconds for a save to show (it takes well under one; the machine is shared)


class PreviewProcess:
    def __init__(self, scene: Path, *args: str) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "xaml3d", "preview", str(scene), *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        self.lines: queue.Queue = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()
        self.url = None
        self.stderr = ""
        try:
            line = self.lines.get(timeout=STARTUP)
        except queue.Empty:
            line = None
        if line is None or not line.startswith("xaml3d preview: http://"):
            self.stop()
            raise AssertionError(f"preview did not start: {line!r} {self.stderr}")
        self.url = line.split()[2]

    def _read(self) -> None:
        for line in self.proc.stdout:
            self.lines.put(line)
        self.lines.put(None)

    def get(self, path: str, headers=None) -> bytes:
        req = urllib.request.Request(self.url + path.lstrip("/"), headers=headers or {})
        with urllib.request.urlopen(req, timeout=30) as r:
            return r.read()

    def state(self) -> dict:
        return json.loads(self.get("state.json"))

    def wait_state(self, after: int, what=lambda s: True) -> dict:
        """The first state newer than version ``after`` for which ``what`` holds."""
        end = time.monotonic() + CHANGE
        while time.monotonic() < end:
            s = self.state()
            if s["version"] > after and what(s):
                return s
            time.sleep(0.05)
        raise AssertionError(f"no new state after version {after}: {self.state()}")

    def stop(self, sig=signal.SIGINT) -> int:
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(timeout=20)
        self.stderr = self.proc.stderr.read()
        return self.proc.returncode

    def __enter__(self) -> PreviewProcess:
        return self

    def __exit__(self, *exc) -> None:
        self.stop()


def save(path: Path, text: str | bytes) -> None:
    """Write ``path`` as an editor that saves by rename does (a new file moved over it)."""
    tmp = path.with_name(path.name + ".saving")
    tmp.write_bytes(text.encode("utf-8") if isinstance(text, str) else text)
    os.replace(tmp, path)
