"""The diagnostics catalogue: every stable code xaml3d can print, with its severity and meaning.

Each stage owns its table (reader, value converters, layout, meshes, cameras, scene checks, --fit,
lens, animation, export, the command line), kept as plain data in a module of this package
(``xaml3d.codes.<stage>``) at the ground of the import layers, so that anything may read a
severity without importing the stage (or the command line) that emits it. The stages re-export
their table under its old name (``xaml3d.scene.mesh.MESH_CODES``...). This module merges them
into one mapping for ``docs/diagnostics.md`` and its test. A code listed by two tables keeps the
first entry (the stage that emits it as a diagnostic); the exception classes' default codes
(``xaml3d.errors``) only fill in codes no table lists.

A code's severity is WPF's verdict (docs/diagnostics.md) and is defined once, in its table:
emitters take it from there (``ReadContext.diag`` and ``ReadContext.error`` look it up, the
scene checks build their diagnostics from their tables), and ``tests/test_severity.py`` checks
that every diagnostic emitted over the reference cases, samples and corpus carries it. Where one
situation has two verdicts (an unknown name among 3D types or among framework elements; a
missing StaticResource or DynamicResource key), there are two codes.

Codes emitted by modules that keep no table of their own (transforms: GEO; renderer: RND; scene
selection: SCN002) are listed here in ``EXTRA_CODES``.
"""

from __future__ import annotations

import functools

import xaml3d.errors as errors
from xaml3d.codes import (
    animation,
    camera,
    checks,
    cli,
    drawing,
    export,
    fit,
    layout,
    lens,
    mesh,
    outputs,
    reader,
    templates,
    values,
)
from xaml3d.errors import ERROR, INFO, WARNING

# (module, table name, required), in merge order: the first table listing a code wins.
TABLES: tuple[tuple[str, str, bool], ...] = (
    ("xaml3d.codes.reader", "READER_CODES", True),
    ("xaml3d.codes.values", "VALUE_CODES", True),
    ("xaml3d.codes.layout", "LAYOUT_CODES", True),
    ("xaml3d.codes.mesh", "MESH_CODES", True),
    ("xaml3d.codes.camera", "CAMERA_CODES", True),
    ("xaml3d.codes.checks", "CHECK_CODES", True),
    ("xaml3d.codes.fit", "FIT_CODES", True),
    ("xaml3d.codes.cli", "CLI_CODES", True),
    ("xaml3d.codes.outputs", "OUTPUT_CODES", True),
    ("xaml3d.codes.lens", "LENS_CODES", True),
    ("xaml3d.codes.animation", "ANIM_CODES", True),
    ("xaml3d.codes.export", "EXPORT_CODES", True),
    ("xaml3d.codes.drawing", "DRAWING_CODES", True),
    ("xaml3d.codes.templates", "TEMPLATE_CODES", True),
)
_MODULES = {
    m.__name__: m
    for m in (reader, values, layout, mesh, camera, checks, fit, cli, outputs, lens, animation,
              export, drawing, templates)
}  # fmt: skip

EXTRA_CODES: dict[str, tuple[str, str]] = {
    "SCN002": (
        ERROR,
        "--viewport names no viewport of the document (index out of range, no such name)",
    ),
    "GEO001": (ERROR, "degenerate points or vectors: the transformation cannot be built"),
    "GEO002": (ERROR, "dependent vectors: the transformation cannot be built"),
    "GEO003": (ERROR, "singular matrix: it cannot be inverted"),
    "GEO004": (ERROR, "a Matrix3D does not have 16 numbers / is not 4x4"),
    "RND001": (ERROR, "image size over the limit (pixels per side or supersampled samples)"),
    "RND002": (WARNING, "nothing was drawn in the image, though the viewport holds models"),
    "RND003": (INFO, "nothing was drawn: the viewport holds no models"),
    "RND004": (
        WARNING,
        "model skipped by the renderer: singular transform or non-finite coordinates",
    ),
    "RND005": (ERROR, "bad render argument (mode, ssaa, background)"),
    "RND006": (ERROR, "unknown output image format (use .png, .jpg, .jpeg or .webp)"),
    "RND007": (ERROR, "the output image cannot be written"),
    "RND008": (
        ERROR,
        "the viewport is laid out empty (LAY001/LAY002): nothing to draw without -W/-H",
    ),
    "RND009": (WARNING, "the image came out one uniform colour, though something was drawn"),
}


def _error_defaults() -> dict[str, tuple[str, str]]:
    """The default code of every XamlError subclass, as a fatal error."""
    out = {}
    for name in dir(errors):
        cls = getattr(errors, name)
        if isinstance(cls, type) and issubclass(cls, errors.XamlError):
            doc = (cls.__doc__ or name).strip().splitlines()[0]
            out.setdefault(cls.default_code, (ERROR, f"{name}: {doc}"))
    return out


def all_codes() -> dict[str, tuple[str, str]]:
    """Every code -> (severity, meaning), sorted by code."""
    merged: dict[str, tuple[str, str]] = {}
    for module, table, _required in TABLES:
        for code, entry in getattr(_MODULES[module], table).items():
            merged.setdefault(code, (entry[0], entry[1]))
    for code, entry in EXTRA_CODES.items():
        merged.setdefault(code, entry)
    for code, entry in _error_defaults().items():
        merged.setdefault(code, entry)
    return dict(sorted(merged.items()))


@functools.cache
def _severities() -> dict[str, str]:
    return {code: entry[0] for code, entry in all_codes().items()}


def severity(code: str) -> str:
    """The severity of ``code`` in its table (KeyError for a code no table lists)."""
    return _severities()[code]
