"""Test configuration: numeric problems raise, the shared corpus is located once, kernels load
through numba."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

np.seterr(all="raise")

# The suite's own processes run the kernels through numba's loading, so that tests may replace
# a kernel module's functions; the native loading of the same machine code is tested, in its
# own processes, by tests/test_native_kernels.py.
os.environ.setdefault("XAML3D_NATIVE", "0")

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "corpus"
SPEC = ROOT.parent / "shared" / "spec"
# The real-world corpus sits beside the clone (CI has it); a bare clone skips what needs it.
needs_corpus = pytest.mark.skipif(
    not CORPUS.is_dir(), reason=f"the shared corpus is absent ({CORPUS})"
)


@pytest.fixture(autouse=True)
def _numpy_raises():
    old = np.seterr(all="raise")
    yield
    np.seterr(**old)


@pytest.fixture
def corpus_dir() -> Path:
    if not CORPUS.is_dir():
        pytest.skip(f"the shared corpus is absent ({CORPUS})")
    return CORPUS


# The quick run, `python -m pytest -m "not slow"`, leaves out what takes long: whole modules of
# reference images, the corpus, browsers and node, worker pools, compiled code and command-line
# runs in subprocesses, and single slow tests (by name). Measured with --durations (README).
SLOW_MODULES = frozenset(
    {
        "test_reference.py",  # 666 reference images
        "test_corpus_cli.py",
        "test_corpus_layout.py",
        "test_corpus_load.py",
        "test_corpus_render.py",
        "test_export_browser.py",  # headless Chromium
        "test_export_validator.py",  # node's glTF validator
        "test_executors.py",  # a dask cluster
        "test_native_kernels.py",  # machine code compiled and loaded in fresh processes
        "test_fuzz.py",
        "test_number_scan.py",  # thousands of property examples, the scanner compiled
        "test_workers.py",  # worker pools
        "test_cli_jobs.py",
        "test_cli_animate_safety.py",  # animations written by the command line
        "test_cli_animate_window.py",
        "test_cli_window_2d_animation.py",
        "test_startup_imports.py",  # fresh interpreters
        # most of their tests run the command line in a subprocess (about a second each)
        "test_cli_render_outputs.py",
        "test_cli_subprocess.py",
        "test_cli_layout.py",
        "test_lens.py",
        "test_diagnostic_locations.py",
        "test_wpf_errors.py",
        "test_gif_delta.py",
        "test_validate_ci.py",
        "test_warnings_first.py",
    }
)
# single tests of the other modules that take seconds (by name: every parameter of it)
SLOW_TESTS = frozenset(
    {
        "tests/test_docs.py::test_api_examples_run",
        "tests/test_frame_session.py::test_frame_passes_and_gif_passes_load_without_numba_registries",
        "tests/test_kernels.py::test_cached_kernels_load_without_numba_registries",
        "tests/test_values.py::test_million_points_one_vectorized_conversion",
        "tests/test_reader_refusals.py::test_behaviors_window_validates_and_renders",
        "tests/test_render_scenes.py::test_near_plane_crossing_no_ghost",
        "tests/test_pass_loop.py::test_flat_solid_colours_loop_like_the_other_paths",
        "tests/test_animation_scene.py::test_cli_animate_formats",
        "tests/test_animation_scene.py::test_cli_animate_gif_transparency_and_frames_dir",
        "tests/test_resources.py::test_missing_key_hint_gives_the_path_as_typed_from_the_current_directory",
        "tests/test_export.py::test_cli_export_refuses_bad_input_without_writing",
    }
)


def pytest_collection_modifyitems(config, items):
    for item in items:
        if item.path.name in SLOW_MODULES or item.nodeid.split("[")[0] in SLOW_TESTS:
            item.add_marker(pytest.mark.slow)
