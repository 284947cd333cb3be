"""Camera validation: every problem of camera-pipeline.md section 9 produces its code."""

from __future__ import annotations

import math

import numpy as np
import pytest

from xaml3d.errors import ERROR, WARNING
from xaml3d.scene.camera_check import CAMERA_CODES, check_camera
from xaml3d.scene.transforms import scaling
from xaml3d.scene.types import MatrixCamera, OrthographicCamera, PerspectiveCamera

NAN, INF = math.nan, math.inf


def codes(camera, width=640, height=480, bounds=None):
    return [d.code for d in check_camera(camera, width, height, bounds)]


class Unknown:
    line = 3


# (camera, viewport, bounds, expected code)
CASES = [
    # errors
    (PerspectiveCamera(look_direction=(0, 0, 0)), None, None, "CAM001"),
    (OrthographicCamera(up_direction=(0, 0, 0)), None, None, "CAM002"),
    (PerspectiveCamera(look_direction=(0, 0, -1), up_direction=(0, 0, 2)), None, None, "CAM003"),
    (PerspectiveCamera(look_direction=(1, 1, 0), up_direction=(-2, -2, 0)), None, None, "CAM003"),
    (PerspectiveCamera(field_of_view=0), None, None, "CAM004"),
    (PerspectiveCamera(field_of_view=180), None, None, "CAM004"),
    (PerspectiveCamera(field_of_view=-30), None, None, "CAM004"),
    (PerspectiveCamera(near_plane_distance=-1), None, None, "CAM005"),
    (PerspectiveCamera(near_plane_distance=2, far_plane_distance=1), None, None, "CAM007"),
    (PerspectiveCamera(near_plane_distance=2, far_plane_distance=2), None, None, "CAM007"),
    (OrthographicCamera(near_plane_distance=-1, far_plane_distance=-2), None, None, "CAM007"),
    (PerspectiveCamera(position=(NAN, 0, 0)), None, None, "CAM008"),
    (PerspectiveCamera(look_direction=(0, 0, -INF)), None, None, "CAM008"),
    (PerspectiveCamera(near_plane_distance=INF), None, None, "CAM008"),
    (PerspectiveCamera(far_plane_distance=NAN), None, None, "CAM008"),
    (PerspectiveCamera(far_plane_distance=-INF), None, None, "CAM008"),
    (PerspectiveCamera(field_of_view=NAN), None, None, "CAM008"),
    (OrthographicCamera(width=INF), None, None, "CAM008"),
    (PerspectiveCamera(transform=np.full((4, 4), NAN)), None, None, "CAM008"),
    (MatrixCamera(projection_matrix=np.full((4, 4), INF)), None, None, "CAM008"),
    (OrthographicCamera(width=0), None, None, "CAM009"),
    (OrthographicCamera(width=-2), None, None, "CAM009"),
    (PerspectiveCamera(), (0, 480), None, "CAM010"),
    (PerspectiveCamera(), (640, -1), None, "CAM010"),
    (PerspectiveCamera(), (NAN, 480), None, "CAM010"),
    (PerspectiveCamera(transform=scaling(1, 1, 0)), None, None, "CAM011"),
    (MatrixCamera(view_matrix=np.zeros((4, 4))), None, None, "CAM012"),
    (MatrixCamera(projection_matrix=np.diag([1.0, 1.0, 0.0, 1.0])), None, None, "CAM012"),
    (Unknown(), None, None, "CAM015"),
    # warnings
    # look (0,-1,-0.01) vs up (0,1,0): sine = 0.01/sqrt(1.0001) -> 0.573 degrees < 1
    (PerspectiveCamera(look_direction=(0, -1, -0.01)), None, None, "CAM101"),
    # far/near = 1000 / 0.01 = 1e5 > 65536
    (PerspectiveCamera(near_plane_distance=0.01, far_plane_distance=1000), None, None, "CAM102"),
    # narrowed to the scene's depth span 0.001..1000 -> n = max(0.01, 0.001), f = 1000: 1e5
    (
        PerspectiveCamera(near_plane_distance=0.01),
        None,
        ((-1, -1, -1000), (1, 1, -0.001)),
        "CAM102",
    ),
    (PerspectiveCamera(is_default=True), None, None, "CAM103"),
    (None, None, None, "CAM104"),
    (PerspectiveCamera(field_of_view=0.5), None, None, "CAM105"),
    (PerspectiveCamera(field_of_view=170), None, None, "CAM106"),
    # a box behind the default camera (it looks down -z from the origin)
    (PerspectiveCamera(), None, ((-1, -1, 5), (1, 1, 6)), "CAM107"),
    # far to the left: at depth 4..5 the view reaches |x| <= 5 tan 22.5 = 2.07
    (PerspectiveCamera(), None, ((-100, -1, -5), (-90, 1, -4)), "CAM107"),
    # beyond a finite far plane
    (PerspectiveCamera(far_plane_distance=10), None, ((-1, -1, -30), (1, 1, -20)), "CAM107"),
    (OrthographicCamera(), None, ((5, -1, -5), (6, 1, -4)), "CAM107"),  # right of width 2
    (MatrixCamera(), None, ((5, 5, 5), (6, 6, 6)), "CAM107"),  # identity: clip = world
    (PerspectiveCamera(), None, ((-5, -5, -5), (5, 5, 5)), "CAM108"),
    # NearPlaneDistance 0 with the eye inside the scene: nothing to narrow the near plane to
    (PerspectiveCamera(near_plane_distance=0), None, ((-5, -5, -5), (5, 5, 5)), "CAM109"),
]


@pytest.mark.parametrize("camera, viewport, bounds, code", CASES)
def test_each_problem_has_its_code(camera, viewport, bounds, code):
    w, h = viewport or (640, 480)
    diags = check_camera(camera, w, h, bounds)
    found = [d for d in diags if d.code == code]
    assert found, f"expected {code}, got {[d.code for d in diags]}"
    d = found[0]
    assert d.severity == CAMERA_CODES[code][0]
    assert d.severity == (ERROR if code < "CAM100" else WARNING)
    assert d.file is None and d.line == getattr(camera, "line", None)
    assert d.message


def test_every_catalogued_code_is_exercised():
    exercised = {case[3] for case in CASES}
    # CAM013 / CAM014 come from orthographic_map's explicit width/height/aspect (test_cameras).
    # CAM006 (NearPlaneDistance 0 as an error) is no longer reported: WPF draws such cameras.
    assert set(CAMERA_CODES) - exercised == {"CAM006", "CAM013", "CAM014"}
    for severity, meaning in CAMERA_CODES.values():
        assert severity in (ERROR, WARNING) and meaning


def test_good_cameras_are_clean():
    assert codes(PerspectiveCamera()) == []
    assert codes(OrthographicCamera(near_plane_distance=-5, far_plane_distance=5)) == []
    assert codes(MatrixCamera()) == []
    # A scene in front of the camera: no bounds warnings.
    cam = PerspectiveCamera(position=(0, 0, 10), near_plane_distance=1, far_plane_distance=100)
    assert codes(cam, bounds=((-1, -1, -1), (1, 1, 1))) == []
    # far +Infinity is allowed (WPF's default)
    assert "CAM008" not in codes(PerspectiveCamera(far_plane_distance=INF))
    # ratio 1000/0.1 = 1e4 < 65536: no depth warning
    assert codes(PerspectiveCamera(near_plane_distance=0.1, far_plane_distance=1000)) == []


def test_depth_ratio_is_narrowed_to_the_scene():
    # user ratio 1e6 / 0.125 = 8e6, but the scene spans depths 9..11: ratio 11/9, as WPF does
    cam = PerspectiveCamera(far_plane_distance=1e6)
    assert codes(cam) == ["CAM102"]
    assert codes(cam, bounds=((-1, -1, -11), (1, 1, -9))) == []
    (d,) = check_camera(PerspectiveCamera(near_plane_distance=0.01, far_plane_distance=1000), 1, 1)
    assert d.code == "CAM102" and "ratio 1e+05" in d.message  # 1000 / 0.01 reported


def test_all_problems_are_reported_together():
    cam = PerspectiveCamera(
        look_direction=(0, 0, 0), field_of_view=200, near_plane_distance=0, far_plane_distance=-1,
        line=12,
    )  # fmt: skip
    found = codes(cam, 0, 0)
    for code in ("CAM010", "CAM001", "CAM004", "CAM007"):
        assert code in found
    assert all(d.line == 12 for d in check_camera(cam, 0, 0))


def test_check_never_raises_on_garbage():
    # strings where numbers belong: reported, not raised
    diags = check_camera(PerspectiveCamera(near_plane_distance="x"), 640, 480)
    assert diags and diags[0].severity == ERROR
    assert check_camera(PerspectiveCamera(), "wide", None)[0].code == "CAM010"


@pytest.mark.parametrize(
    ("box", "cause"),
    [
        (((-1, -1, 5.5), (1, 1, 7)), "behind the camera"),  # camera at z = 5 looks down -z
        (((-1, -1, 4.95), (1, 1, 4.96)), "closer to the camera than the near plane"),
        (((-1, -1, -200), (1, 1, -150)), "beyond the far plane"),
        (((40, -1, -1), (42, 1, 1)), "past its right edge"),
    ],
)
def test_scene_out_of_view_names_the_real_cause(box, cause):
    cam = PerspectiveCamera(position=(0, 0, 5), near_plane_distance=0.125, far_plane_distance=100)
    found = [d for d in check_camera(cam, 40, 30, box) if d.code == "CAM107"]
    assert len(found) == 1 and cause in found[0].message, found


def test_near_plane_zero_is_narrowed_to_the_scene_as_wpf_does():
    # WPF narrows near to the scene's nearest depth (9 here): no error, no depth warning
    cam = PerspectiveCamera(position=(0, 0, 10), near_plane_distance=0, line=4)
    assert codes(cam) == []
    assert codes(cam, bounds=((-1, -1, -1), (1, 1, 1))) == []
    # the narrowed ratio still z-fights when the scene is deep: 1e6 / 9 > 65536
    assert codes(cam, bounds=((-1, -1, -1e6), (1, 1, 1))) == ["CAM102"]
