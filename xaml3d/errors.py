"""Problems found in a scene: fatal errors (exceptions) and recoverable diagnostics.

Every problem carries a stable code (see docs/diagnostics.md), a severity and, where known, the
file, line and column it comes from. Both print as ``file:line:col: severity CODE message``, the
form editors and CI annotate.
"""

from __future__ import annotations

from dataclasses import dataclass

ERROR = "error"
WARNING = "warning"
INFO = "info"
SEVERITIES = (ERROR, WARNING, INFO)


def _location(file: str | None, line: int | None, column: int | None) -> str:
    parts = [file or "<input>"]
    if line is not None:
        parts.append(str(line))
        parts.append(str(column if column is not None else 1))
    return ":".join(parts)


@dataclass(frozen=True)
class Diagnostic:
    """A recoverable problem: something was skipped, defaulted or will not look as meant."""

    code: str
    severity: str
    message: str
    file: str | None = None
    line: int | None = None
    column: int | None = None

    def format(self) -> str:
        where = _location(self.file, self.line, self.column)
        return f"{where}: {self.severity} {self.code} {self.message}"

    def __str__(self) -> str:
        return self.format()

    def to_dict(self) -> dict:
        return {
            "file": self.file,
            "line": self.line,
            "column": self.column,
            "severity": self.severity,
            "code": self.code,
            "message": self.message,
        }


class XamlError(Exception):
    """Base of every fatal xaml3d error: nothing sensible can be drawn or read."""

    default_code = "X3D000"

    def __init__(
        self,
        message: str,
        *,
        code: str | None = None,
        file: str | None = None,
        line: int | None = None,
        column: int | None = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        self.code = code or self.default_code
        self.file = file
        self.line = line
        self.column = column

    def with_location(self, file=None, line=None, column=None) -> XamlError:
        """Fill in a location the raiser did not know (keeps what is already set)."""
        if self.file is None:
            self.file = file
        if self.line is None:
            self.line = line
        if self.column is None:
            self.column = column
        return self

    def as_diagnostic(self) -> Diagnostic:
        return Diagnostic(self.code, ERROR, self.message, self.file, self.line, self.column)

    def format(self) -> str:
        return f"{_location(self.file, self.line, self.column)}: error {self.code} {self.message}"

    def __str__(self) -> str:
        return self.format()


class XamlSyntaxError(XamlError):
    """The text is not well-formed XML, or is hostile (entities, DTD, size/depth limits)."""

    default_code = "XML001"


class ValueSyntaxError(XamlError):
    """An attribute value does not follow WPF's type-converter syntax."""

    default_code = "VAL001"
    # (the string converted, 0-based index of the offending character in it) when the
    # converter knows it: the reader then points the column at that character
    at: tuple[str, int] | None = None


class ResourceError(XamlError):
    """A resource could not be resolved (missing key, cycle, unreadable dictionary)."""

    default_code = "RES001"


class SceneError(XamlError):
    """The document holds no renderable scene (no Viewport3D, bad viewport selection...)."""

    default_code = "SCN001"


class GeometryError(XamlError, ValueError):
    """A transformation cannot be built: degenerate points or vectors, singular matrices."""

    default_code = "GEO001"


class CameraError(XamlError):
    """The camera cannot produce an image (see camera-pipeline section 9)."""

    default_code = "CAM001"


class RenderError(XamlError):
    """Rendering was refused or failed (size cap, output not writable...)."""

    default_code = "RND001"
