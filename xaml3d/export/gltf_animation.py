"""Storyboards as one glTF animation: translation / rotation / scale channels, sampled.

The Scene's animation is read through ``xaml3d.export.timeline`` only. Every animated model,
light and the camera is sampled at ``SAMPLE_RATE`` frames per second over one cycle (Forever
repeats counted once) and written as LINEAR channels of its node, so easing, key splines, paths
and every curve WPF has come out as WPF computes them, to within the sampling (EXP010). What
glTF's channels cannot carry (a camera's FieldOfView or Width, colours, materials, meshes) is
named in an EXP009 warning.
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import partial

import numpy as np

from xaml3d.errors import CameraError, SceneError
from xaml3d.export import trs
from xaml3d.export.gltf_camera import gltf_camera
from xaml3d.export.gltf_scene import light_node
from xaml3d.export.timeline import Clip

SAMPLE_RATE = 30.0  # frames per second of the exported channels
MAX_SAMPLES = 3600


def _times(clip: Clip) -> np.ndarray:
    want = clip.seconds * SAMPLE_RATE  # inf for a cycle of 1e308 s: the most samples
    n = max(2, int(math.ceil(want)) + 1) if want < MAX_SAMPLES else MAX_SAMPLES
    # glTF's times are single precision: a longer cycle is sampled up to the last one it holds
    seconds = min(clip.seconds, float(np.finfo(np.float32).max))
    return np.linspace(0.0, seconds, n) if seconds > 0 else np.zeros(1)


def _differs(a, b) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return not np.array_equal(np.asarray(a), np.asarray(b))
    return a != b


def sample(clip: Clip, vp_index: int, progress=None) -> tuple[np.ndarray, list] | None:
    """(sample times, the viewport at each) of ``clip``, or None when it has no length."""
    times = _times(clip)
    if times.shape[0] < 2:
        return None
    frames = []
    # a moment whose animated values all equal an earlier one's is that moment's Scene (a
    # hold, an AutoReverse coming back, a clock too slow to move): its very viewport, so
    # that nothing of it is evaluated or compared again
    seen: dict = {}
    for k, t in enumerate(times):
        try:
            if clip.at_values is None:
                frames.append(clip.at(float(t)).viewport(vp_index))
            else:
                scene, values = clip.at_values(float(t))
                vp = seen.get(values)
                if vp is None:
                    vp = seen[values] = scene.viewport(vp_index)
                frames.append(vp)
        except SceneError:  # a viewport that vanishes: nothing to sample
            return None
        if progress is not None:
            progress(k + 1, len(times))
    return times, frames


def add_animation(export, clip: Clip, times: np.ndarray, frames: list) -> None:
    """Add the channels of the sampled ``frames`` to ``export``'s document (a ViewportExport
    built with these frames)."""
    base = frames[0]
    tracks: dict = {}  # node or (outer, inner) nodes -> world matrices per sample
    lost: set[str] = set()
    # A frame shares every object the storyboards leave alone with the first (scene_at replaces
    # only what a track reaches): only the models and lights the tracks reach are looked at,
    # so that sampling costs what the animated values cost, not the whole scene at each time.
    moving_models, moving_lights = clip.moving(base.index)
    if all(len(f.models) == len(base.models) for f in frames):
        for i in sorted(i for i in moving_models if i < len(base.models)):
            m0 = base.models[i]
            column = [f.models[i] for f in frames]
            if all(m is m0 for m in column):
                continue
            node = export.model_nodes.get(i)
            if node is not None:
                worlds = [np.asarray(m.world) for m in column]
                if any(_differs(w, worlds[0]) for w in worlds):
                    tracks[node] = worlds
            for m in column:
                if m is m0:
                    continue
                if m.mesh is not m0.mesh and _differs(m.mesh.positions, m0.mesh.positions):
                    lost.add("mesh positions")
                # (not ==: a brush's transform is an array; scene_at replaces what it changes)
                if m.material is not m0.material or m.back_material is not m0.back_material:
                    lost.add("materials and brushes")
    else:
        lost.add("models appearing or disappearing")
    if export.camera_node is not None:
        _camera_track(export, frames, tracks, lost, moving_models)
    if all(len(f.lights) == len(base.lights) for f in frames):
        for i, node in export.light_nodes.items():
            if i not in moving_lights or all(f.lights[i] is base.lights[i] for f in frames):
                continue  # not animated
            got = [light_node(f.lights[i]) for f in frames]
            if any(g is None for g in got):
                continue
            worlds = [g[1] for g in got]
            if any(_differs(w, worlds[0]) for w in worlds):
                tracks[node] = worlds
            if any(g[0] != got[0][0] for g in got):
                lost.add("light colours, ranges or cones")
    for what in sorted(lost):
        export.note("EXP009", f"the storyboards animate {what}, which glTF cannot animate: "
                    "the exported animation leaves it at its first value")  # fmt: skip
    if not tracks:
        return
    _write(export, times, tracks)
    note = (f"storyboards exported as transforms sampled at {SAMPLE_RATE:g} per second "
            f"(LINEAR), {clip.seconds:g} s")  # fmt: skip
    export.note("EXP010", note)
    if clip.endless:
        export.note("EXP011", f"an animation has a Forever Duration: its first {clip.seconds:g}"
                    " s are exported")  # fmt: skip


def _bounds_of(frames, moving_models):
    """A function giving a frame's ``bounds()``: the models no track reaches are measured once
    (every frame shares them), the others in each frame asked about; the same numbers (the
    union of the two boxes, min and max being exact)."""
    base = frames[0]
    moving = [i for i in sorted(moving_models) if i < len(base.models)]
    still = None

    def bounds(f):
        nonlocal still
        if len(f.models) != len(base.models):
            return f.bounds()
        if still is None:
            kept = tuple(m for i, m in enumerate(base.models) if i not in moving_models)
            still = (replace(base, models=kept).bounds(),)
        box = replace(f, models=tuple(f.models[i] for i in moving)).bounds()
        if still[0] is None or box is None:
            return box if still[0] is None else still[0]
        return np.minimum(still[0][0], box[0]), np.maximum(still[0][1], box[1])

    return bounds


def _camera_track(export, frames, tracks, lost, moving_models=frozenset()) -> None:
    worlds, cams = [], []
    got, before = None, None
    bounds = _bounds_of(frames, moving_models)
    for f in frames:
        if got is None or f.camera is not before:  # an unchanged camera: the same matrices
            try:
                got = gltf_camera(f, bounds=partial(bounds, f))
            except CameraError:
                lost.add("the camera into a state WPF cannot draw")
                return
            before = f.camera
        if got is None:
            return
        cams.append(got[0])
        worlds.append(got[1])
    if any(_differs(w, worlds[0]) for w in worlds):
        tracks[export.camera_node] = worlds
    if any(c != cams[0] for c in cams):
        lost.add("the camera's FieldOfView, Width or planes")


def _continuous(quats) -> np.ndarray:
    """Quaternions with signs chosen so each sample is the shorter way from the one before."""
    q = np.array(quats, dtype=np.float64)
    for k in range(1, len(q)):
        if float(q[k] @ q[k - 1]) < 0:
            q[k] = -q[k]
    return q


def _write(export, times, tracks) -> None:
    doc = export.doc
    time_acc = doc.accessor(times.astype(np.float32), bounds=True)
    samplers, channels = [], []
    for node, worlds in tracks.items():
        nested = isinstance(node, tuple)
        parts = [trs.split(w) if nested else trs.decompose(w) for w in worlds]
        if any(p is None for p in parts):
            export.note("EXP009", "an animated transform collapses (a zero scale) or becomes "
                        "projective at some moment: its animation is not exported")  # fmt: skip
            continue
        if nested:
            inner = [p[1] for p in parts]
            parts = [p[0] for p in parts]
        t = np.array([p[0] for p in parts])
        s = np.array([p[2] for p in parts])
        paths = [(node[0] if nested else node, "translation", t),
                 (node[0] if nested else node, "rotation", _continuous([p[1] for p in parts])),
                 (node[0] if nested else node, "scale", s)]  # fmt: skip
        if nested:
            paths.append((node[1], "rotation", _continuous(inner)))
        for target, path, values in paths:
            # values near the doubles' range (a light placed at 1e308, turned) differ by more
            # than the range: not close, and refused as beyond single precision just below
            with np.errstate(over="ignore", invalid="ignore"):
                still = np.allclose(values, values[0], rtol=0, atol=1e-12)
            if still:
                continue
            if not np.all(np.abs(values) <= np.finfo(np.float32).max):
                msg = (f"an animated {path} goes beyond single precision (3.4e38), which "
                       "glTF cannot hold: its animation is not exported")  # fmt: skip
                export.note("EXP009", msg)
                continue
            out = doc.accessor(values.astype(np.float32))
            samplers.append({"input": time_acc, "output": out, "interpolation": "LINEAR"})
            channels.append({"sampler": len(samplers) - 1,
                             "target": {"node": target, "path": path}})  # fmt: skip
    if channels:
        doc.add("animations", {"name": "Storyboards", "samplers": samplers, "channels": channels})
