"""The long structured fuzz run: documents written from the reader's vocabulary with values at
the edges of their domains (tests/fuzz_documents.py), each run through load, validate, a render
at a moment of its storyboards, the window picture, the glTF export and animate's frame count,
with numpy raising on every floating-point error and every warning an error. What escapes (a
traceback, a RuntimeWarning, a document that takes over --timeout seconds) is written to
--out as the document and its traceback, and the run goes on. Nightly, in bounded memory:

    prlimit --as=3000000000 -- nice python tools/fuzz.py --examples 100000 --out fuzz-found/

(a document past the memory limit ends in a MemoryError, which is reported like any other
escape). The last line gives the counts; the exit status is 1 when anything was found.
"""

from __future__ import annotations

import argparse
import signal
import sys
import time
import traceback
import warnings
from collections import Counter
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from fuzz_documents import document, random_picker, run_document  # noqa: E402


class Hang(Exception):
    """A document that took longer than --timeout seconds."""


def _alarm(signum, frame):
    raise Hang("over the time limit")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--examples", type=int, default=10000, help="documents to run")
    ap.add_argument("--seed", type=int, default=0, help="the first document's seed")
    ap.add_argument("--timeout", type=int, default=30, help="seconds a document may take")
    ap.add_argument("--out", type=Path, default=Path("fuzz-found"), help="where escapes go")
    ap.add_argument("--every", type=int, default=1000, help="print progress every N documents")
    args = ap.parse_args(argv)
    signal.signal(signal.SIGALRM, _alarm)
    np.seterr(all="raise", under="ignore")  # an underflow to 0 never changes a picture
    found: Counter[str] = Counter()
    slowest = (0.0, -1)
    started = time.monotonic()
    for i in range(args.seed, args.seed + args.examples):
        text = document(random_picker(i))
        t0 = time.monotonic()
        signal.alarm(args.timeout)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("error")
                run_document(text)
        except (Exception, RecursionError, MemoryError) as exc:  # noqa: BLE001 (what escaped)
            frames = traceback.extract_tb(exc.__traceback__)
            where = (
                f"{frames[-1].filename.rsplit('/', 1)[-1]}:{frames[-1].lineno}" if frames else "?"
            )
            key = f"{type(exc).__name__} at {where}"
            if found[key] < 3:  # a few documents of each kind are enough to fix it
                args.out.mkdir(parents=True, exist_ok=True)
                stem = args.out / f"seed{i}"
                stem.with_suffix(".xaml").write_text(text, encoding="utf-8")
                stem.with_suffix(".txt").write_text(
                    "".join(traceback.format_exception(exc)), encoding="utf-8"
                )
            found[key] += 1
        finally:
            signal.alarm(0)
        took = time.monotonic() - t0
        slowest = max(slowest, (took, i))
        done = i - args.seed + 1
        if done % args.every == 0 or done == args.examples:
            rate = done / (time.monotonic() - started)
            print(f"{done} documents, {rate:.1f}/s, {sum(found.values())} escapes of "
                  f"{len(found)} kinds, slowest {slowest[0]:.2f} s (seed {slowest[1]})",
                  flush=True)  # fmt: skip
    for key, n in found.most_common():
        print(f"  {n:6d}  {key}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
