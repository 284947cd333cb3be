"""The glTF 2.0 container: JSON, one binary buffer, accessors, and the .glb / .gltf encodings.

Written directly with numpy and ``json`` rather than through pygltflib or trimesh: the exporter
needs only a few dozen lines of container code (buffer views aligned to 4 bytes, accessors with
exact float32 min/max, the GLB chunk layout), and this keeps the run-time dependencies to the
project's five. ``.glb`` holds the buffer as its BIN chunk; ``.gltf`` is one self-contained file
with the buffer as a base64 ``data:`` URI.
"""

from __future__ import annotations

import base64
import io
import json
import struct

import numpy as np
from PIL import Image

FLOAT, UINT32, UINT16 = 5126, 5125, 5123
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
_TYPES = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4", 16: "MAT4"}
GLB_MAGIC, GLB_JSON, GLB_BIN = 0x46546C67, 0x4E4F534A, 0x004E4942


class Document:
    """A glTF document under construction: ``gltf`` is the JSON tree, ``blob`` the buffer."""

    def __init__(self, generator: str) -> None:
        self.gltf: dict = {"asset": {"version": "2.0", "generator": generator}}
        self.blob = bytearray()
        self.extensions: set[str] = set()

    def add(self, key: str, item: dict) -> int:
        """Append ``item`` to the top-level array ``key``; its index."""
        items = self.gltf.setdefault(key, [])
        items.append(item)
        return len(items) - 1

    def use_extension(self, name: str) -> None:
        self.extensions.add(name)

    def view(self, data: bytes, target: int | None = None) -> int:
        """A buffer view over ``data`` appended to the buffer (4-byte aligned)."""
        self.blob.extend(b"\0" * (-len(self.blob) % 4))
        item = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target is not None:
            item["target"] = target
        self.blob.extend(data)
        return self.add("bufferViews", item)

    def accessor(self, array: np.ndarray, *, target: int | None = None, bounds=False) -> int:
        """An accessor over ``array`` (N,) or (N, k): float32, or uint32/uint16 for indices.
        ``bounds``: min/max of the STORED values (the validator compares them exactly)."""
        array = np.ascontiguousarray(array)
        if array.dtype == np.float32:
            component = FLOAT
        elif array.dtype == np.uint32:
            component = UINT32
        elif array.dtype == np.uint16:
            component = UINT16
        else:
            raise TypeError(f"unsupported accessor dtype {array.dtype}")
        width = 1 if array.ndim == 1 else int(array.shape[1])
        item = {
            "bufferView": self.view(array.tobytes(), target),
            "componentType": component,
            "count": int(array.shape[0]),
            "type": _TYPES[width],
        }
        if bounds and array.shape[0]:
            flat = array.reshape(array.shape[0], width)
            item["min"] = [_number(v) for v in flat.min(axis=0)]
            item["max"] = [_number(v) for v in flat.max(axis=0)]
        return self.add("accessors", item)

    def image_png(self, rgba: np.ndarray) -> int:
        """A PNG image (from an (H, W, 4) uint8 array) stored in the buffer; its image index."""

        out = io.BytesIO()
        Image.fromarray(np.ascontiguousarray(rgba), mode="RGBA").save(out, format="PNG")
        view = self.view(out.getvalue())
        return self.add("images", {"bufferView": view, "mimeType": "image/png"})

    def finished(self, uri: bool) -> dict:
        """The JSON tree with the buffer declared (as a data: URI when ``uri``)."""
        gltf = dict(self.gltf)
        self.blob.extend(b"\0" * (-len(self.blob) % 4))
        if self.blob:
            buffer = {"byteLength": len(self.blob)}
            if uri:
                data = base64.b64encode(bytes(self.blob)).decode("ascii")
                buffer["uri"] = "data:application/octet-stream;base64," + data
            gltf["buffers"] = [buffer]
        if self.extensions:
            gltf["extensionsUsed"] = sorted(self.extensions)
        return gltf

    def glb(self) -> bytes:
        """The binary container: header, JSON chunk (space padded), BIN chunk (zero padded)."""
        text = json.dumps(self.finished(uri=False), separators=(",", ":"), allow_nan=False)
        body = text.encode("utf-8")
        body += b" " * (-len(body) % 4)
        chunks = struct.pack("<II", len(body), GLB_JSON) + body
        if self.blob:
            chunks += struct.pack("<II", len(self.blob), GLB_BIN) + bytes(self.blob)
        return struct.pack("<III", GLB_MAGIC, 2, 12 + len(chunks)) + chunks

    def gltf_text(self) -> bytes:
        text = json.dumps(self.finished(uri=True), indent=1, allow_nan=False)
        return text.encode("utf-8")


def _number(v) -> float | int:
    return int(v) if isinstance(v, np.integer) else float(v)


def read_glb(data: bytes) -> tuple[dict, bytes]:
    """(JSON tree, BIN chunk) of a .glb file (for reading an export back)."""
    magic, version, length = struct.unpack_from("<III", data, 0)
    if magic != GLB_MAGIC or version != 2 or length != len(data):
        raise ValueError("not a glTF 2.0 binary file")
    size, kind = struct.unpack_from("<II", data, 12)
    if kind != GLB_JSON:
        raise ValueError("the first GLB chunk is not JSON")
    gltf = json.loads(data[20 : 20 + size].decode("utf-8"))
    rest = 20 + size
    blob = b""
    if rest < len(data):
        bsize, bkind = struct.unpack_from("<II", data, rest)
        if bkind == GLB_BIN:
            blob = data[rest + 8 : rest + 8 + bsize]
    return gltf, blob
