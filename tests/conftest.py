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
# runs in subprocesses, and single slow tests (by name): those that took a second or more of
# CPU time (the process and its children, which a shared machine's load does not inflate as it
# does --durations' wall-clock times). `python -m pytest -q` still runs everything.
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
        "test_preview.py",  # a preview server per test, files edited and watched
        "test_preview_browser.py",  # headless Chromium
        "test_notebook.py",  # a Jupyter kernel
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
        # the command line in subprocesses, a second or more of CPU each
        "tests/test_animation_scene.py::test_storyboard_option_accepts_the_storyboards_own_name",
        "tests/test_checks.py::test_varying_brush_without_texture_coordinates_is_chk008",
        "tests/test_cli_camera_depth.py::test_a_point_beyond_the_effective_far_plane_is_marked",
        "tests/test_cli_camera_labels.py::test_camera_labels_the_product_with_the_cameras_own_matrices",
        "tests/test_cli_camera_labels.py::test_the_labelled_factors_multiply_to_the_product",
        "tests/test_cli_dictionary.py::test_render_and_export_say_what_validate_says",
        "tests/test_cli_dictionary.py::test_validate_checks_each_resource_as_a_scene_using_it_would",
        "tests/test_cli_empty_layout.py::test_animate_and_camera_say_the_same_render_error",
        "tests/test_cli_empty_layout.py::test_one_of_width_and_height_gives_a_square",
        "tests/test_cli_empty_layout.py::test_validate_warns_and_render_refuses_with_one_render_error",
        "tests/test_cli_moot_findings.py::test_fit_reports_the_camera_it_draws",
        "tests/test_cli_moot_findings.py::test_storyboard_option_silences_the_warning_of_the_one_it_begins",
        "tests/test_cli_option_messages.py::test_animate_duration_zero_names_duration",
        "tests/test_cli_option_messages.py::test_export_batch_ends_with_a_summary_line",
        "tests/test_cli_value_words.py::test_camera_marks_default_only_what_the_markup_does_not_give",
        "tests/test_diagnostics_examples.py::test_cam102_warns_on_the_ratio_narrowed_to_the_scene_depth_span",
        "tests/test_export.py::test_camera_json_view_equals_the_export_to_1e9",
        "tests/test_export.py::test_cli_export_one_file_and_a_batch",
        "tests/test_export.py::test_cli_says_what_obj_and_stl_lose_without_verbose",
        "tests/test_follow_on_warnings.py::test_an_unreadable_camera_value_is_not_followed_by_findings_about_its_default",
        "tests/test_framework_members.py::test_the_command_line_refuses_and_says_why",
        "tests/test_gif_stream.py::test_webp_is_streamed_and_is_the_file_pillow_writes_from_a_list",
        "tests/test_output_names.py::test_a_255_byte_name_works_for_every_output",
        "tests/test_output_names.py::test_an_over_long_name_is_a_usage_error",
        "tests/test_progress.py::test_animate_says_the_frame_count_and_cycle_up_front",
        "tests/test_progress.py::test_export_reports_sampling_progress_in_a_log",
        "tests/test_raster.py::test_compiled_set_up_is_bit_identical",
        "tests/test_special_outputs.py::test_animate_into_a_fifo_and_a_frame_node",
        "tests/test_special_outputs.py::test_batch_onto_a_full_node_fails_that_scene_only",
    }
)


def pytest_collection_modifyitems(config, items):
    for item in items:
        if item.path.name in SLOW_MODULES or item.nodeid.split("[")[0] in SLOW_TESTS:
            item.add_marker(pytest.mark.slow)
