"""Render every file of a real-world XAML corpus in every mode and write a report.

    python tools/conformance.py [CORPUS_DIR] [--out docs]
    python tools/conformance.py --sources DIR      # only the "Gathered files" section


Writes ``docs/conformance.md`` (per file: status -- the command line's verdict, "refused
(errors)" for a file whose findings hold an error --, warnings, refusal, triangles, times, running
animations), ``docs/conformance-sheet.png`` (a contact sheet of every shaded render) and, for
every file that animates, ``docs/conformance-anim/<file>.gif`` (one cycle of what runs at load;
a storyboard that only code-behind begins is begun by name). The default corpus is
``../shared/corpus`` beside the checkout.

The section "Gathered files" lists Viewport3D XAML gathered from public repositories (not kept
in the repository): ``tools/conformance_sources.tsv`` holds, per file, the repository, path,
commit, what WPF does with it, and xaml3d's verdict. ``--sources DIR`` re-runs ``xaml3d
validate`` over the downloaded copies (``DIR/manifest.tsv``: repository, path, commit, local
file name, WPF's verdict, tab-separated), rewrites that table and the section of
``docs/conformance.md``; a full run keeps the section.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
from collections import Counter
from pathlib import Path

from PIL import Image, ImageDraw

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from xaml3d.corpus import MODES, companions_for, run_file  # noqa: E402

THUMB = (240, 180)
GIF_WIDTH, GIF_FPS, GIF_MAX_SECONDS = 160, 12, 4.0
BACKDROP = (176, 196, 222)  # the contact sheet's blue-grey: shows what is transparent


def _scaled(rgba):
    """A window frame at the report's GIF width."""
    import numpy as np

    h, w = rgba.shape[:2]
    size = (GIF_WIDTH, max(1, round(h * GIF_WIDTH / w)))
    return np.asarray(Image.fromarray(rgba, "RGBA").resize(size, Image.LANCZOS))


def animate_file(path: Path, out_dir: Path) -> str:
    """Write ``out_dir/<stem>.gif`` when the file animates; the table cell saying what runs."""
    import math

    from xaml3d import frame_times, load, render_frames, save_animation
    from xaml3d.animation.moment import picture_moves
    from xaml3d.errors import XamlError

    try:
        scene = load(path, resources=companions_for(path))
    except XamlError:
        return "-"
    tl = scene.timeline
    if tl is None or not scene.viewports:
        return "0"
    named = None
    running = len(tl.running_animations())
    cell = str(running)
    if not running:  # begun by code-behind (or a click): begin the first that animates
        for name in tl.storyboard_names():
            if tl.running_animations(name):
                named = name
                cell = f"0 ({len(tl.running_animations(name))} by name: {name})"
                break
        else:
            return "0"
    whole, once = tl.cycle(named), tl.one_cycle(named)
    length = whole if math.isfinite(whole) and whole > 0 else once
    if not (math.isfinite(length) and length > 0):
        length = 1.0
    length = min(length, GIF_MAX_SECONDS)
    try:
        times = frame_times(0.0, length, GIF_FPS)
        # a viewport that its own RenderTransform moves is drawn as WPF shows it: the whole
        # window (its box alone would show the picture sliding out of it), scaled to the width
        window = picture_moves(scene, 0, times, named) is not None
        frames = [
            _scaled(r.rgba) if window else r.rgba
            for _, r in render_frames(
                scene, times, named, width=None if window else GIF_WIDTH, background=BACKDROP,
                window=window,
            )
        ]  # fmt: skip
        out_dir.mkdir(parents=True, exist_ok=True)
        save_animation(frames, out_dir / f"{path.stem}.gif", length)
    except XamlError as exc:
        return f"{cell}; not drawn: {exc.message}"
    return f"{cell} ([gif](conformance-anim/{path.stem}.gif), {length:g} s)"


def contact_sheet(results, path: Path) -> None:
    cells = [(r.name, m.image) for r in results for m in r.modes if m.mode == "shaded" and m.image]
    if not cells:
        return
    cols = 5
    rows = (len(cells) + cols - 1) // cols
    sheet = Image.new("RGB", (cols * THUMB[0], rows * (THUMB[1] + 16)), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    for k, (name, img) in enumerate(cells):
        x, y = (k % cols) * THUMB[0], (k // cols) * (THUMB[1] + 16)
        thumb = img.copy()
        thumb.thumbnail(THUMB)
        # A flat blue-grey backdrop shows what is transparent (a checkerboard would be confused
        # with the grey checker that stands in for missing images).
        bg = Image.new("RGB", thumb.size, (176, 196, 222))
        bg.paste(thumb, (0, 0), thumb)
        sheet.paste(bg, (x, y + 16))
        draw.text((x + 2, y + 2), name[:38], fill=(0, 0, 0))
    sheet.save(path)


def report(results, corpus: Path, anims: dict) -> str:
    counts = Counter(r.status for r in results)
    lines = [
        "# Real-world conformance",
        "",
        "Generated by `python tools/conformance.py`: every file of the shared corpus "
        f"(`{corpus.name}/`, {len(results)} files) loaded with its companion resources and "
        f"rendered in every mode ({', '.join(MODES)}) at the size WPF's layout gives its first "
        "viewport (docs/layout.md; at t = 0: WPF's first frame, Loaded storyboards applied); "
        "files whose root is a Window, Page or UserControl are also drawn whole as "
        "`render --window` does. The animations column counts the animations "
        "running at load; a file whose storyboard only code-behind begins is animated with that "
        "storyboard begun by name (`--storyboard`). Each animated file has a GIF in "
        "`conformance-anim/` (one cycle, at most 4 s, 160 px wide, 12 frames per second, on "
        "the contact sheet's blue-grey; the whole window, as `animate --window` draws it, "
        "when the first viewport's own RenderTransform moves it).",
        "",
        "The status is the command line's verdict: `rendered with warnings` when `xaml3d "
        "validate` lists warnings (the diagnostics column counts its warnings and errors), "
        "`refused (errors)` when it lists an error, so that `xaml3d render` refuses the file "
        "(exit 1; the timings and the picture are those of `render --lenient`), `refused` "
        "when loading or rendering stops, `no viewport` for resource dictionaries.",
        "",
        "| status | files |",
        "|---|---|",
    ]
    lines += [f"| {k} | {v} |" for k, v in sorted(counts.items())]
    lines += [
        "",
        "| file | status | viewports | layout size | --window | triangles | lights | load s | "
        + " | ".join(f"{m} s" for m in MODES)
        + " | animations | diagnostics |",
        "|---|---|---|---|---|---|---|---|" + "---|" * len(MODES) + "---|---|",
    ]
    for r in results:
        times = {m.mode: (f"{m.seconds:.2f}" if not m.error else "refused") for m in r.modes}
        codes = Counter(d.code for d in r.warnings)
        diag = ", ".join(f"{c}x{n}" if n > 1 else c for c, n in sorted(codes.items()))
        if r.refusal:
            diag = (diag + "; " if diag else "") + "refused: " + r.refusal.replace("|", "\\|")
        sizes = ", ".join(f"{w:g} x {h:g}" for w, h, _ in r.sizes) or "-"
        win = "-" if r.window is None else r.window.replace("|", "\\|")
        lines.append(
            f"| {r.name} | {r.status} | {r.viewports} | {sizes} | {win} | {r.triangles} | "
            f"{r.lights} | "
            f"{r.load_seconds:.2f} | "
            + " | ".join(times.get(m, "-") for m in MODES)
            + f" | {anims.get(r.name, '-')} | {diag} |"
        )
    lines += ["", "## How each viewport's size was derived", ""]
    for r in results:
        for i, (w, h, how) in enumerate(r.sizes):
            lines.append(f"- {r.name} viewport {i}: {w:g} x {h:g} from {how}")
    lines += ["", "The contact sheet of the shaded renders: `conformance-sheet.png`.", ""]
    return "\n".join(lines)


SOURCES = ROOT / "tools" / "conformance_sources.tsv"
SOURCES_TITLE = "## Gathered files"
_FINDING = re.compile(r"^\S+:\d+:\d+: (error|warning) (\w+) ")


def validate_verdict(path: Path) -> tuple[str, str]:
    """(verdict, codes) of ``xaml3d validate`` on one file: "loads", "loads with warnings" or
    "refused", and its error and warning codes (sorted, with counts)."""
    run = subprocess.run(
        [sys.executable, "-m", "xaml3d", "validate", str(path)],
        capture_output=True, text=True, cwd=path.parent, timeout=300,
    )  # fmt: skip
    found = [m.groups() for m in map(_FINDING.match, run.stdout.splitlines()) if m]
    errors = sorted({c for sev, c in found if sev == "error"})
    warnings = Counter(c for sev, c in found if sev == "warning")
    if run.returncode != 0:
        return "refused", ", ".join(errors) or run.stderr.strip().splitlines()[-1]
    codes = ", ".join(f"{c}x{n}" if n > 1 else c for c, n in sorted(warnings.items()))
    return ("loads with warnings" if warnings else "loads"), codes


def gather_sources(folder: Path) -> list[list[str]]:
    """Validate every file of ``folder/manifest.tsv``; the rows of conformance_sources.tsv."""
    rows = []
    for line in (folder / "manifest.tsv").read_text(encoding="utf-8").splitlines():
        repo, path, commit, local, wpf = line.split("\t")
        verdict, codes = validate_verdict(folder / local)
        rows.append([repo, path, commit, wpf, verdict, codes])
        print(f"{local}: {verdict} {codes}", file=sys.stderr)
    return rows


def sources_section(rows: list[list[str]]) -> str:
    agree = sum(1 for r in rows if r[3].startswith("refuses") == (r[4] == "refused"))
    lines = [
        SOURCES_TITLE,
        "",
        f"{len(rows)} Viewport3D files gathered from public repositories (WPF's own test suite "
        "dotnet/wpf-test, tutorials and sample applications), beyond the shared corpus, each "
        "run through `xaml3d validate` (`python tools/conformance.py --sources DIR`; the files "
        "are not kept here). The WPF column says what WPF's loader does with the file: files "
        "that need their own project's assembly (a `clr-namespace` type, a toolkit) load in "
        "that project. xaml3d's verdict agrees with WPF's for "
        f"{agree} of {len(rows)}; each refusal names WPF's reason.",
        "",
        "| repository | path | commit | WPF | xaml3d | codes |",
        "|---|---|---|---|---|---|",
    ]
    for repo, path, commit, wpf, verdict, codes in rows:
        cells = [repo, f"`{path}`", commit[:12], wpf, verdict, codes]
        lines.append("| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |")
    # SCN001 (no Viewport3D) is xaml3d's own reason, never WPF's: say so for each such file
    odd = [r for r in rows if "SCN001" in r[5]]
    if odd:
        lines += [
            "",
            "Refused with xaml3d's own reason, not WPF's (SCN001, no Viewport3D to draw):",
        ]
        lines += [f"- {r[0]} `{r[1]}`: WPF {r[3]}" for r in odd]
    return "\n".join(lines) + "\n"


def read_sources() -> list[list[str]]:
    if not SOURCES.exists():
        return []
    return [ln.split("\t") for ln in SOURCES.read_text(encoding="utf-8").splitlines() if ln]


def with_sources(text: str, rows: list[list[str]]) -> str:
    """``text`` (conformance.md) with its "Gathered files" section replaced by ``rows``."""
    head = text.split(SOURCES_TITLE, 1)[0].rstrip("\n") + "\n\n"
    return head + sources_section(rows) if rows else head


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("corpus", nargs="?", default=str(ROOT.parent / "shared" / "corpus"))
    ap.add_argument("--out", default=str(ROOT / "docs"))
    ap.add_argument("--sources", help="folder of gathered files with manifest.tsv")
    args = ap.parse_args(argv)
    corpus, out = Path(args.corpus), Path(args.out)
    if args.sources:
        rows = gather_sources(Path(args.sources))
        SOURCES.write_text("".join("\t".join(r) + "\n" for r in rows), encoding="utf-8")
        page = out / "conformance.md"
        page.write_text(with_sources(page.read_text(encoding="utf-8"), rows), encoding="utf-8")
        print(f"wrote {SOURCES} and the section of {page}", file=sys.stderr)
        return 0
    files = sorted(corpus.glob("*.xaml"))
    if not files:
        print(f"{corpus}: no .xaml files", file=sys.stderr)
        return 1
    results = []
    anims = {}
    out.mkdir(parents=True, exist_ok=True)
    for k, f in enumerate(files, 1):
        r = run_file(f, window=True)
        results.append(r)
        anims[f.name] = animate_file(f, out / "conformance-anim")
        print(f"[{k}/{len(files)}] {f.name}: {r.status}, animations {anims[f.name]}",
              file=sys.stderr)  # fmt: skip
    page = report(results, corpus, anims)
    (out / "conformance.md").write_text(with_sources(page, read_sources()), encoding="utf-8")
    contact_sheet(results, out / "conformance-sheet.png")
    print(f"wrote {out / 'conformance.md'}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
