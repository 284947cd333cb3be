"""Draws reference cases in a process of its own and prints what it drew (for
tests/test_native_kernels.py): per case the SHA-256 of the picture and depth arrays, and
whether this process imported numba and which kernels it ran natively or through numba.

    python tests/_native_probe.py CASE.xaml... > out.json
    python tests/_native_probe.py --animate SCENE.xaml OUT.gif > out.json
"""

from __future__ import annotations

import hashlib
import json
import sys


def main(paths: list[str]) -> None:
    import xaml3d
    from xaml3d.render import accel

    # the kernels loaded whatever the frames' work (XAML3D_KERNELS=numba would also make the
    # reader's number scanner import numba for every list)
    accel.plan(float("inf"), 0)
    drawn = {}
    if paths[0] == "--animate":  # an animation's frames (frame sessions) and its GIF
        scene = xaml3d.load(paths[1])
        frames = []
        for t, r in xaml3d.render_frames(scene, xaml3d.frame_times(0, 1, 30)):
            drawn[f"{t:.4f}"] = hashlib.sha256(r.rgba.tobytes()).hexdigest()
            frames.append(r.rgba)
        xaml3d.save_animation(frames, paths[2], 1.0)
    else:
        for path in paths:
            for opts in ({}, {"mode": "flat"}, {"ssaa": 2}):
                r = xaml3d.render_arrays(path, **opts)
                h = hashlib.sha256(r.rgba.tobytes())
                h.update(r.depth.tobytes())
                drawn[f"{path} {sorted(opts.items())}"] = h.hexdigest()
    k = accel.active()
    print(
        json.dumps(
            {
                "drawn": drawn,
                "numba_imported": "numba" in sys.modules,
                "native": list(getattr(k, "native_kernels", [])),
                "through_numba": sorted(getattr(k, "numba_kernels", [])),
            }
        )
    )


if __name__ == "__main__":
    main(sys.argv[1:])
