"""``xaml3d animate``: a scene's storyboards -> GIF, APNG (.png), WebP, or numbered PNGs.

Thin layer over ``xaml3d.render.frames`` and ``xaml3d.output.animation``: picks the times
(``--fps``, ``--start``, ``--end``/``--duration``, by default one full cycle of what runs at
load), renders each frame as ``render`` would (in worker processes, in order), streams the
frames to the output as they come (a frame directory, an APNG and a WebP frame by frame; a GIF's
frames quantized and the PNGs of an APNG or a directory encoded in the workers, only palette
images held for a GIF), reports progress (a bar on a terminal, a line every few seconds
elsewhere), and writes the file atomically. Bad input is one ``file:line:col: error CODE
message`` line and exit status 1.
"""

from __future__ import annotations

import functools
import math
from collections import deque
from pathlib import Path

import click

from xaml3d.animation.moment import picture_moves, scene_at
from xaml3d.cli_common import (
    FiniteFloat,
    ProgressLines,
    Sizes,
    display_name,
    echo_diagnostics,
    exit_on_input_error,
    failure_line,
    io_error,
    load_scene,
    no_app_option,
    output_path,
    parse_background,
    parse_time,  # noqa: F401 (the time option's parser, also this module's interface)
    resources_option,
    scene_files_read,
    stderr_is_terminal,
    storyboard_option,
    time_callback,
    warn_option,
    window_size_option,
    with_file,
)
from xaml3d.cli_outputs import (
    OUTPUT_CODES,
    FrameSequence,
    animation_target,
    overwritten_input,
    remove_stale,
    stale_frames,
    stale_message,
)
from xaml3d.cli_render_extras import (
    animate_lens_options,
    check_lens_camera,
    check_request,
    lens_arguments,
)
from xaml3d.codes.animation import ANIM_CODES
from xaml3d.errors import ERROR, WARNING, CameraError, Diagnostic, XamlError
from xaml3d.findings import begun_by_name, has_errors, scene_findings
from xaml3d.findings import lenient as lenient_findings
from xaml3d.output.animation import (
    frame_names,
    gif_picture,
    link_gif,
    png_frame,
    write_apng,
    write_gif,
    write_webp,
)
from xaml3d.output.images import png_bytes
from xaml3d.render import frames as frames_module
from xaml3d.render.settings import RenderSettings
from xaml3d.render.workers import default_jobs

DEFAULT_LENGTH = 1.0  # seconds drawn when nothing runs or a Duration is Forever
MAX_FRAMES = 18000  # 10 minutes at 30 fps: past it a run is refused (ANIM017, --max-frames)
LONG_RUN = 90  # frames from which the run's plan is printed up front (3 s at 30 fps and more)


HELP = """Render a scene's animations to an animated image or numbered frames.

The output format follows -o: .gif, .png (APNG), .webp, or DIR/ for frame_0000.png ...
(--clean removes frame files an earlier, longer run left there). By default one full
cycle of what starts at load is drawn (a Forever repeat: one iteration, with a note)
at 30 frames per second.

\b
Examples:
  xaml3d animate spin.xaml -o spin.gif
  xaml3d animate spin.xaml -o spin.png --fps 25 -W 320 --background White
  xaml3d animate spin.xaml -o frames/ --start 1 --end 3
  xaml3d animate menu.xaml -o click.webp --storyboard OnClick
  xaml3d animate app.xaml -o app.gif --window      # the whole window, each frame

\b
Exit status: 0 written (warnings allowed), 1 the scene could not be animated, 2 usage error.
"""


@click.command("animate", help=HELP)
@click.argument("scene", metavar="SCENE")
@click.option("-o", "--output", required=True, metavar="FILE|DIR/", callback=output_path,
              help="Output file or DIR/.")  # fmt: skip
@click.option("--fps", type=FiniteFloat(0, 120, min_open=True), default=30.0,
              show_default=True, help="Frames per second.")  # fmt: skip
@click.option("--start", callback=time_callback, default="0", show_default=True,
              metavar="T", help="Time of the first frame.")  # fmt: skip
@click.option("--end", callback=time_callback, metavar="T",
              help="Time where the animation stops (default: --start + --duration).")  # fmt: skip
@click.option("--duration", callback=time_callback, metavar="T",
              help="Length drawn (default: one full cycle of what runs).")  # fmt: skip
@click.option("--loop", type=click.IntRange(min=0), default=0, show_default=True,
              help="Times the file plays (0: for ever).")  # fmt: skip
@click.option("--max-frames", type=click.IntRange(min=1), default=MAX_FRAMES, show_default=True,
              help="Refuse a run of more frames than this (length x --fps).")  # fmt: skip
@click.option("--clean", is_flag=True, help="With -o DIR/: delete the frame files "
              "(frame_NNNN.png) of an earlier run that this one does not replace.")  # fmt: skip
@storyboard_option
@click.option("-W", "--width", type=click.IntRange(min=1), help="Width in pixels.")
@click.option("-H", "--height", type=click.IntRange(min=1), help="Height in pixels.")
@click.option("--mode", type=click.Choice(["shaded", "flat", "wireframe"]), default="shaded",
              show_default=True, help="Drawing mode.")  # fmt: skip
@click.option("--background", metavar="COLOR", help="Fill colour, any WPF syntax "
              "(default: transparent).")  # fmt: skip
@click.option("--ssaa", type=click.IntRange(1, 4), help="Supersampling factor per axis, 1..4.")
@click.option("--msaa", type=click.IntRange(1, 4), help="Multisampling per axis, 1..4 (default 2).")
@click.option("--viewport", metavar="INDEX|NAME", help="Which Viewport3D (default: the first).")
@click.option("--window", is_flag=True, help="Draw the root's whole client area in each "
              "frame (every viewport, the panels and controls), as render --window --time "
              "T.")  # fmt: skip
@window_size_option
@resources_option
@no_app_option
@click.option("-j", "--jobs", type=click.IntRange(1),
              help="Worker processes for the frames (default: the number of cores).")  # fmt: skip
@click.option("--lenient", is_flag=True, help="Animate a scene with errors anyway: each "
              "error is reported as a warning, WPF's default used for what could not be "
              "read.")  # fmt: skip
@click.option("-q", "--quiet", is_flag=True, help="Do not print warnings (errors still are).")
@click.option("-v", "--verbose", is_flag=True, help="Also print informational diagnostics.")
@animate_lens_options
def animate_command(scene, output, fps, start, end, duration, loop, max_frames, clean,
                    storyboard, width, height, mode, background, ssaa, msaa, viewport, window,
                    window_size, resources, no_app, jobs, lenient, quiet, verbose,
                    extras) -> None:  # fmt: skip
    if window and viewport is not None:
        raise click.UsageError("--window draws every viewport: drop --viewport")
    if window and (width is not None or height is not None):
        raise click.UsageError("-W/-H size one viewport; with --window use --window-size "
                               "(the root's client size)")  # fmt: skip
    check_request(extras, (scene,), output, mode, window, window)
    if end is None and duration is not None and duration <= 0:
        # said in the option the user gave (--end would be derived from it), before reading
        raise click.BadParameter(f"--duration must be > 0 (it is {duration:g} s)")
    to_dir = animation_target(output)  # the format, before anything is read (exit 2)

    bg = parse_background(None, None, background)
    if (ssaa or 1) > 1 and (msaa or 1) > 1:
        raise click.UsageError("choose one of --ssaa and --msaa")
    if clean and not to_dir:
        warn_option("--clean applies to a directory output (-o DIR/) only")  # fmt: skip
    name = display_name(scene)
    ctx = click.get_current_context()
    if to_dir and Path(output).exists() and not Path(output).is_dir():
        msg = f"{output} is a file, not a directory: it cannot hold the frames"
        click.echo(io_error(name, msg), err=True)
        ctx.exit(1)
    inputs = [Path(p) for p in (scene, *resources) if p != "-"]
    with exit_on_input_error(name):
        if not to_dir and _refused(name, [Path(output)], inputs):  # before reading the scene
            ctx.exit(1)
        sc = load_scene(scene, resources, window_size, discover_app=not no_app)
    inputs += [Path(p) for p in scene_files_read(sc)]  # App.xaml, dictionaries, images
    file = sc.file or name
    diags = [with_file(d, file) for d in begun_by_name(sc.diagnostics, sc, storyboard)]
    shown: set = set()  # printed before the first frame: not again at the end
    sequence = None
    try:
        start = start or 0.0
        if end is None:
            if duration is None:
                duration, note, code = _default_length(sc, storyboard)
                if note:
                    diags.append(_note(file, note, code))
            end = start + duration
        if end <= start:
            raise click.BadParameter(f"--end ({end:g} s) must come after --start ({start:g} s)")
        sizes = Sizes(RenderSettings(width=width, height=height))  # once per viewport
        diags = _verdict(sc, (start, storyboard), sizes, name, lenient, diags, quiet, verbose)

        if Path(output).suffix.lower() == ".gif" and not to_dir and fps > 50:
            slow = f"--fps {fps:g}: GIF frames shorter than 20 ms are shown at 100 ms by most "
            diags.append(_note(file, slow + "viewers (use --fps 50 or less)", "ANIM012"))
        vp = sc.viewport(None if window else viewport)  # SCN001 when there is none
        check_lens_camera(extras, vp)
        # --aperture, --stereo, --line-*: every frame; the size is computed once
        settings = RenderSettings(viewport=vp.index, mode=mode, background=bg, ssaa=ssaa,
                                  msaa=msaa, time=None, **lens_arguments(extras))  # fmt: skip
        if not window:  # --window: each viewport at its laid-out box
            size = sizes(vp)
            settings = settings.replace(width=size.width, height=size.height, aspect=size.aspect)
        count = frames_module.frame_count(start, end, fps)
        if count > max_frames:  # before any list of times is built
            raise XamlError(
                f"{end - start:g} s from {start:g} s at {fps:g} fps is {count:.4g} frames, more "
                f"than --max-frames {max_frames}: give --duration or --end (the part to draw), "
                "lower --fps, or raise --max-frames",
                code="ANIM017",
            )
        times = frames_module.frame_times(start, end, fps)
        if not window:
            moved = _moving_viewport(sc, vp.index, times, storyboard, file)
            if moved is not None:
                diags.append(moved)
        # Every path this run writes, checked before the first frame is drawn.
        names = frame_names(len(times)) if to_dir else []
        if _refused(name, [Path(output) / n for n in names] if to_dir else [Path(output)], inputs):
            ctx.exit(1)
        stale = stale_frames(Path(output), names) if to_dir else []
        sequence = FrameSequence(Path(output), names) if to_dir else None
        jobs = default_jobs() if jobs is None else jobs
        folder = str(Path(output) if to_dir else Path(output).parent)
        # what is known before the first frame (the findings: a missing image, a light...)
        # is said before the progress, not after a long run
        echo_diagnostics(diags, quiet=quiet, verbose=verbose)
        shown.update(diags)
        if not quiet and (verbose or len(times) >= LONG_RUN):
            click.echo(_plan_line(name, sc, storyboard, len(times), fps, end - start), err=True)

        # nothing animates at load (ANIM015): one picture, drawn once and repeated
        still = sc.timeline is None or not sc.timeline.running(storyboard)

        def drawn(prepare, link=None):
            """The frames in time order, each ``prepare``d in the process that drew it (and
            each run of them ``link``ed there), with the progress shown and the render's
            diagnostics kept (counted again from zero when the GIF writer asks for the frames
            again)."""
            diags[:] = [d for d in diags if d.code != "RND002"]
            it = frames_module.render_frames(  # looked up at call time: it may be wrapped
                sc, times, storyboard, jobs=jobs, settings=settings, folders=[folder],
                prepare=prepare, link=link, depth=False, window=window, still=still,
            )  # fmt: skip
            for r in _progress(it, len(times), name, quiet):
                yield _keep(r, diags, file)

        gif = Path(output).suffix.lower() == ".gif" and not to_dir
        apng = Path(output).suffix.lower() in (".png", ".apng") and not to_dir
        if gif:
            # Streamed: each frame is quantized by the worker that drew it, compressed there as
            # its difference from the frame before (``output.gif_frames.link_gif``), and
            # written as it comes (``output.animation.write_gif``).
            beneath = None if bg is not None or window else _opaque_beneath(vp)
            if bg is not None:
                matte = tuple(round(255 * c) for c in bg[:3])
            else:
                matte = beneath or (255, 255, 255)

            def source(plan):
                return drawn(functools.partial(_gif_ready, plan=plan), _gif_linked)

            flattened = write_gif(source, output, end - start, len(times), loop=loop, matte=matte)
        elif sequence is not None:  # to disk frame by frame, encoded by the workers
            for png in drawn(_png_ready):
                sequence.add(png)
        elif apng:  # streamed too, one frame held, each encoded by the worker that drew it
            write_apng(drawn(_apng_ready), output, end - start, len(times), loop=loop)
        else:  # WebP: streamed too, one RGBA frame held
            write_webp(drawn(_lean), output, end - start, len(times), loop=loop)
        empty = [d for d in diags if d.code == "RND002"]
        if len(empty) < len(times):  # an empty frame is part of an animation: no warning
            diags = [d for d in diags if d.code != "RND002"]
        if sequence is not None:
            sequence.commit()
        elif gif:
            if flattened:
                diags.append(_note(file, _flattened_message(bg, beneath), "ANIM013"))
        if stale and clean:
            stale = remove_stale(stale, inputs)  # only after the new sequence is complete
        if stale:
            diags.append(_note(file, stale_message(output, stale, len(names), clean), "IO004"))
    except XamlError as exc:
        echo_diagnostics(_unshown(diags, shown), quiet=quiet, verbose=verbose)
        click.echo(exc.with_location(file=name).format(), err=True)
        ctx.exit(1)
    except (OSError, ValueError, ArithmeticError, RecursionError) as exc:
        echo_diagnostics(_unshown(diags, shown), quiet=quiet, verbose=verbose)
        click.echo(failure_line(name, exc), err=True)
        ctx.exit(1)
    finally:
        if sequence is not None:
            sequence.discard()  # a failure or Ctrl-C: no frame file of this run is left
    # The file is written: exit 0. An error left here is the frames' own (the findings at
    # --start had none, or --lenient turned them into warnings): a camera a storyboard drives
    # out of range at some moments, which WPF draws as it can at those frames.
    if lenient:
        diags = _lenient_empty(diags)  # the frames' errors the findings said already
    diags = [_while_animating(d) if d.severity == ERROR else d for d in diags]
    echo_diagnostics(_unshown(diags, shown), quiet=quiet, verbose=verbose)


def _while_animating(d: Diagnostic) -> Diagnostic:
    msg = f"{d.message} [reached while animating: those frames are drawn as WPF draws them]"
    return Diagnostic(d.code, WARNING, msg, d.file, d.line, d.column)


def _lenient_empty(diags: list) -> list:
    """--lenient: the frames' camera errors that the findings already reported (as warnings,
    which say why the frames are empty, as WPF draws nothing) are not errors again."""
    known = {(d.code, d.file, d.line, d.column) for d in diags if d.severity == WARNING}
    return [d for d in diags
            if d.severity != ERROR or (d.code, d.file, d.line, d.column) not in known]  # fmt: skip


def _unshown(diags, shown: set) -> list:
    return [d for d in diags if d not in shown]


def _plan_line(name: str, sc, storyboard, count: int, fps: float, length: float) -> str:
    """What the run draws, said before the first frame: the frame count and the cycle."""
    tl = sc.timeline
    if tl is None or not tl.running(storyboard):
        cycle = "nothing animates"
    else:
        whole, once = tl.cycle(storyboard), tl.one_cycle(storyboard)
        if not math.isinf(whole):
            cycle = f"one cycle: {whole:g} s"
        elif math.isinf(once):
            cycle = "a Duration is Forever"
        else:
            cycle = f"repeats for ever, one iteration: {once:g} s"
    return f"{name}: animating {count} frames ({length:g} s at {fps:g} fps; {cycle})"


def _moving_viewport(sc, index: int, times, storyboard, file: str) -> Diagnostic | None:
    """ANIM016 when the frames move viewport ``index``'s picture by its own RenderTransform (or
    one of an element around it): WPF moves the viewport over the window, while the frames of
    one viewport are its box, which the picture then slides within and out of."""
    found = picture_moves(sc, index, times, storyboard)
    if found is None:
        return None
    track, own = found
    whose = "its own RenderTransform" if own else "the RenderTransform of an element around it"
    msg = (f"viewport {index} is moved by {whose} ({track.target}): WPF moves it over the "
           "window, but these frames are the viewport's own box, which its picture slides "
           "within and out of; --window draws the whole window in each frame")  # fmt: skip
    return Diagnostic("ANIM016", ANIM_CODES["ANIM016"][0], msg, file, track.line, track.column)


def _verdict(sc, moment, sizes, name: str, lenient: bool, diags, quiet: bool, verbose: bool):
    """The findings ``render --time START`` reports (``xaml3d.findings``, the same as
    ``validate``) at ``moment`` (start, storyboard) and the render ``sizes`` (-W, -H): a scene
    with errors is not animated (exit 1) unless --lenient, which reports each error as a
    warning. Returns the diagnostics to print after the frames."""

    def size_of(vp):
        try:
            size = sizes(vp)
        except CameraError:  # an empty viewport: the camera check reports it (CAM010)
            return (vp.width, vp.height)
        return (size.width, size.height)

    findings = scene_findings(scene_at(sc, *moment), size_of, name, moment[1])
    if not has_errors(findings):
        return [*findings, *(d for d in diags if d not in findings)]
    if not lenient or not sc.viewports:
        echo_diagnostics(findings, quiet=quiet, verbose=verbose)
        if sc.viewports:
            click.echo(f"{name}: not animated: the scene has errors (--lenient animates it)",
                       err=True)  # fmt: skip
        click.get_current_context().exit(1)
    return [*lenient_findings(findings), *(d for d in diags if d not in findings)]


def _refused(name: str, outputs: list[Path], inputs: list[Path]) -> bool:
    """Print IO002 and return True when an output would replace a file the scene reads."""
    hit = overwritten_input(outputs, inputs)
    if hit is not None:
        msg = f"refusing to write {hit[0]} over the input file {hit[1]}"
        click.echo(io_error(name, msg, "IO002"), err=True)
    return hit is not None


def _opaque_beneath(vp) -> tuple[int, int, int] | None:
    """The colour WPF shows beneath the viewport (its nearest laid-out ancestor's Background)
    as 8-bit sRGB when it is one opaque colour, else None."""
    from xaml3d.scene.types import SolidColorBrush

    b = vp.background
    if not isinstance(b, SolidColorBrush) or b.color[3] * b.opacity < 1.0:
        return None
    return tuple(round(255 * c) for c in b.color[:3])


def _flattened_message(bg, beneath=None) -> str:
    """ANIM013: the GIF's frames were flattened onto the --background colour made opaque, else
    onto the opaque colour beneath the viewport (its nearest Background), else white, as GIF's
    1-bit transparency would lose their partly transparent pixels."""
    if bg is not None:
        onto = "the --background colour, made opaque"
    elif beneath is not None:
        onto = "the Background beneath the viewport (#{:02X}{:02X}{:02X})".format(*beneath)
    else:
        onto = "white"
    return (f"GIF keeps only 1-bit transparency: frames flattened onto {onto} to show their "
            "partly transparent pixels (translucent materials, light added over transparency, "
            "or the blur of --aperture); "
            "use .png (APNG) or .webp to keep alpha")  # fmt: skip


def _lean(r):
    """A frame's Rendering without its depth buffers (not written by ``animate``): less to send
    back from a worker process."""
    r.depth = r.distance = r.ids = None
    return r


def _gif_ready(r, plan):
    """A frame's Rendering with its picture quantized for the GIF writer under ``plan``
    (``gif_picture``) where it was drawn: in parallel."""
    r = _lean(r)
    r.rgba = gif_picture(r.rgba, plan)
    return r


def _gif_linked(results):
    """A run of consecutive frames' Renderings (``_gif_ready``) with their pictures compressed
    as GIF frames where they were drawn, each as its difference from the one before
    (``link_gif``): few bytes to send back."""
    kept: deque = deque()

    def pictures():
        for r in results:
            kept.append(r)
            yield r.rgba

    for g in link_gif(pictures()):
        r = kept.popleft()
        r.rgba = g
        yield r


def _png_ready(r):
    """A frame's Rendering with its picture encoded as the PNG file of a frame directory
    (``png_bytes``, the bytes ``save_image`` writes) where it was drawn."""
    r = _lean(r)
    r.rgba = png_bytes(r.rgba)
    return r


def _apng_ready(r):
    """A frame's Rendering with its picture encoded for the APNG writer (``png_frame``) where
    it was drawn: in parallel, and compressed bytes to send back."""
    r = _lean(r)
    r.rgba = png_frame(r.rgba)
    return r


def _progress(it, total: int, name: str, quiet: bool):
    """The items of ``it``, with a progress bar on a terminal, else a line every few seconds."""
    if stderr_is_terminal() and not quiet:
        with click.progressbar(it, length=total, label="animating",
                               file=click.get_text_stream("stderr")) as bar:  # fmt: skip
            for _, r in bar:
                yield r
        return
    report = ProgressLines(f"{name}: animating", total) if not quiet else None
    for i, (_, r) in enumerate(it, 1):
        yield r
        if report is not None:
            report(i)
    if report is not None:
        report.finish("; finishing the file")


def _keep(result, diags: list, file: str):
    for d in result.diagnostics:
        d = with_file(d, file)
        if d not in diags or d.code == "RND002":  # RND002 counted per frame
            diags.append(d)
    return result.rgba


def _default_length(sc, storyboard) -> tuple[float, str | None, str]:
    """One full cycle of what runs (a Forever repeat: one iteration), with a note and its code
    when the drawn length is not the whole animation: a warning (ANIM015) when there is no
    cycle at all, since the frames then show nothing moving or an arbitrary stretch."""
    tl = sc.timeline
    if tl is None or not tl.running(storyboard):
        still = f"nothing animates at load: {DEFAULT_LENGTH:g} s of one still picture is written"
        return DEFAULT_LENGTH, still, "ANIM015"
    whole, once = tl.cycle(storyboard), tl.one_cycle(storyboard)
    if math.isinf(once) or once <= 0:
        why = "a Duration is Forever" if math.isinf(once) else "the animations take no time"
        return DEFAULT_LENGTH, f"{why}: {DEFAULT_LENGTH:g} s drawn (use --duration)", "ANIM015"
    if math.isinf(whole):
        once_note = f"the animation repeats for ever: one iteration ({once:g} s) drawn"
        return once, once_note, "ANIM011"
    return whole, None, "ANIM011"


def _note(file: str, message: str, code: str = "ANIM011"):
    return Diagnostic(code, {**ANIM_CODES, **OUTPUT_CODES}[code][0], message, file)
