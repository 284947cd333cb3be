"""How a compiled kernel's arguments and results cross into its machine code: one flat block.

numba compiles a kernel to a native function with its own calling convention
(``numba.core.callconv.CPUCallConv``): ``i32 f(ret*, excinfo**, <arguments flattened>)``, where
every array is flattened into its fields (meminfo, parent, size, itemsize, data pointer, shape,
strides) and the i32 is a status (0: a value, -2: None, anything else: an exception was raised).
A small trampoline (``trampoline_ir``), compiled once beside the kernel's cached machine code,
reads those flattened arguments from one block of 8-byte slots, calls the kernel and stores the
status: so a call from Python is ``struct.pack`` of the slots and one ctypes call, with no numba
in the process.

``describe`` turns numba's argument types into specs (plain tuples, kept in a JSON manifest);
``Signature`` checks a call's arguments against one of them (the same dtype, dimensions,
contiguity and writability numba would have typed them as: anything else is not this machine
code, so the caller falls back to numba's own dispatch) and packs them.
"""

from __future__ import annotations

import struct
import weakref

import numpy as np

# numba's array data model, flattened (numba.core.datamodel.models.ArrayModel): meminfo and
# parent pointers, nitems, itemsize, data pointer, then shape and strides (ndim each).
_ARRAY_HEAD = ("ptr", "ptr", "i64", "i64", "ptr")

# scalar numba types a kernel may take, with their LLVM argument type and block packing
_SCALARS = {
    "int64": ("i64", "q"),
    "uint64": ("i64", "Q"),
    "int32": ("i32", "i4x"),
    "uint32": ("i32", "I4x"),
    "int16": ("i16", "h6x"),
    "uint16": ("i16", "H6x"),
    "int8": ("i8", "b7x"),
    "uint8": ("i8", "B7x"),
    "float64": ("double", "d"),
    "float32": ("float", "f4x"),
    "bool": ("i8", "q"),  # numba passes a boolean as a byte
}
# results a kernel may return (each one 8-byte slot of the result struct)
_RESULTS = {"int64": "q", "float64": "d", "bool": "?"}

STATUS_VALUE = 0
STATUS_NONE = -2  # numba's RETCODE_NONE: the function returned None


class KernelRaised(RuntimeError):
    """A kernel's machine code reported an exception (a defect: kernels do not raise)."""

    def __init__(self, status: int):
        super().__init__(f"a compiled kernel stopped with status {status}")


class Unsupported(Exception):
    """A kernel whose arguments or result this ABI does not carry (it stays on numba)."""


def describe(argtypes, restype) -> tuple[list, list]:
    """Specs of numba's argument types and result type: ``["a", dtype, ndim, readonly]`` for a
    C-contiguous aligned array, ``["s", name]`` for a scalar; the result as a list of scalar
    names, empty for None, with "tuple" first for a tuple (``Signature.result_of``)."""
    args = []
    for t in argtypes:
        name = type(t).__name__
        if name == "Array":
            if t.layout != "C" or not t.aligned or str(t.dtype) not in _DTYPES:
                raise Unsupported(f"array {t}")
            args.append(["a", str(t.dtype), int(t.ndim), bool(not t.mutable)])
        elif str(t) in _SCALARS:
            args.append(["s", str(t)])
        else:
            raise Unsupported(f"argument {t}")
    rname = type(restype).__name__
    if str(restype) == "none":
        result = []
    elif rname in ("UniTuple", "Tuple"):
        result = ["tuple", *(str(x) for x in restype.types)]
    else:
        result = [str(restype)]
    for r in result[1:] if result[:1] == ["tuple"] else result:
        if r not in _RESULTS:
            raise Unsupported(f"result {restype}")
    if "bool" in result and len(result) > 1:
        raise Unsupported(f"result {restype}")  # a tuple's booleans are not 8-byte slots
    return args, result


_DTYPES = {
    name: np.dtype(name)
    for name in ("float64", "float32", "int64", "int32", "uint8", "uint32", "uint64", "bool")
}


def llvm_types(args: list) -> list[str]:
    """The flattened LLVM argument types of the specs (after ret* and excinfo**)."""
    out = []
    for spec in args:
        if spec[0] == "a":
            out.extend(_ARRAY_HEAD)
            out.extend(["i64"] * (2 * spec[2]))
        else:
            out.append(_SCALARS[spec[1]][0])
    return out


def typed_pointers() -> bool:
    """Whether the installed llvmlite's LLVM parses typed pointers (``i64*``) rather than
    opaque ones (``ptr``): LLVM 14 (llvmlite 0.42, 0.43) knows only typed ones; LLVM 15 and 16
    (llvmlite 0.44) both, typed unless llvmlite turned opaque ones on; LLVM 17 on only opaque
    ones. IR in the other form fails to parse (after a warning LLVM prints itself)."""
    import llvmlite
    import llvmlite.binding as llvm

    major = llvm.llvm_version_info[0]
    if major < 15:
        return True
    if major >= 17:
        return False
    return not getattr(llvmlite, "opaque_pointers_enabled", True)


def trampoline_ir(
    symbol: str, native: str, args: list, triple: str, layout: str, typed: bool = False
) -> str:
    """LLVM IR of ``void symbol(i64* block, ret*, i32* status)``: load each flattened argument
    from its 8-byte slot, call the kernel's native function, store its status. Pointers are
    opaque (``ptr``), or typed when ``typed`` (``typed_pointers``: every pointer the kernel
    takes as ``i8*``; the types of a declaration do not reach the object, only its symbol)."""
    types = llvm_types(args)
    if typed:
        p, blk, exc, status = "i8*", "i64*", "i8**", "i32*"
        types = ["i8*" if t == "ptr" else t for t in types]
    else:
        p = blk = exc = status = "ptr"
    lines = [
        f'target triple = "{triple}"',
        f'target datalayout = "{layout}"',
        f'declare i32 @"{native}"({p}, {exc}{"".join(", " + t for t in types)})',
        f'define void @"{symbol}"({blk} %blk, {p} %ret, {status} %status) {{',
        "entry:",
        f"  %exc = alloca {p}",
        f"  store {p} null, {exc} %exc",
    ]
    call = []
    for k, t in enumerate(types):
        lines.append(f"  %p{k} = getelementptr i64, {blk} %blk, i64 {k}")
        lines.append(f"  %v{k} = load i64, {blk} %p{k}")
        if t == "i64":
            call.append(f"i64 %v{k}")
            continue
        if t == p:
            lines.append(f"  %a{k} = inttoptr i64 %v{k} to {p}")
        elif t == "double":
            lines.append(f"  %a{k} = bitcast i64 %v{k} to double")
        elif t == "float":
            lines.append(f"  %t{k} = trunc i64 %v{k} to i32")
            lines.append(f"  %a{k} = bitcast i32 %t{k} to float")
        elif t in ("i32", "i16", "i8"):
            lines.append(f"  %a{k} = trunc i64 %v{k} to {t}")
        else:  # pragma: no cover - llvm_types makes only the types above
            raise Unsupported(t)
        call.append(f"{t} %a{k}")
    lines.append(
        f'  %r = call i32 @"{native}"({p} %ret, {exc} %exc{"".join(", " + c for c in call)})'
    )
    lines.append(f"  store i32 %r, {status} %status")
    lines.append("  ret void")
    lines.append("}")
    return "\n".join(lines) + "\n"


class Signature:
    """One compiled version of a kernel: checks a call's arguments and packs them."""

    __slots__ = ("args", "result", "fmt", "rfmt", "rsize", "tuple", "_checks", "_formats", "_tails")

    def __init__(self, args: list, result: list):
        self.args = args
        self.tuple = result[:1] == ["tuple"]
        self.result = result = result[1:] if self.tuple else result
        formats = []
        checks = []
        for spec in args:
            if spec[0] == "a":
                formats.append("QQqqQ" + "q" * (2 * spec[2]))
                checks.append((True, (_DTYPES[spec[1]], spec[2], not spec[3])))
            else:
                formats.append(_SCALARS[spec[1]][1])
                checks.append((False, _SCALAR_CHECK[spec[1]]))
        self.fmt = struct.Struct("<" + "".join(formats))
        self.rfmt = struct.Struct("<" + "".join(_RESULTS[r] for r in result))
        self.rsize = max(8, self.rfmt.size)
        self._checks = checks
        self._formats = formats
        self._tails: dict[int, Signature] = {}

    def head_size(self, n: int) -> int:
        """Bytes of the block the first ``n`` arguments fill (each fills whole 8-byte slots)."""
        return struct.calcsize("<" + "".join(self._formats[:n]))

    def tail(self, n: int) -> Signature:
        """A signature of the arguments from the ``n``-th on: packs a block's end (``bind``)."""
        found = self._tails.get(n)
        if found is None:
            found = Signature(self.args[n:], [])
            self._tails[n] = found
        return found

    def result_of(self, status: int, buffer) -> object:
        """The kernel's result from its status and result buffer, as numba returns it."""
        if status == STATUS_NONE or (status == STATUS_VALUE and not self.result):
            return None
        if status != STATUS_VALUE:
            raise KernelRaised(status)
        values = self.rfmt.unpack_from(buffer)
        return values if self.tuple else values[0]

    def pack(self, values: tuple) -> bytes | None:
        """The argument block, or None when an argument is not of this version's types (as
        numba would type it: e.g. a read-only array for a writable one, a float for an int)."""
        if len(values) != len(self._checks):
            return None
        slots = []
        add = slots.append
        extend = slots.extend
        for (array, check), v in zip(self._checks, values, strict=True):
            if array:
                fields = _array_fields(v, check)
                if fields is None:
                    return None
                extend(fields)
            else:
                if type(v) not in check:
                    return None
                add(v)
        try:
            return self.fmt.pack(*slots)
        except (struct.error, OverflowError):  # an int beyond int64: numba types it uint64
            return None


# The flattened fields of arrays seen lately, by id, with a weak reference that proves the
# array is the same object (an id is reused only after its object died, which kills the
# reference): loops pass the same buffers call after call (a frame's bands, a pass's chunks),
# and reading an array's fields and flags costs several times the call itself. An array's data
# pointer cannot move while the array lives (numpy refuses to resize a referenced array); its
# shape, strides and dtype are compared again on every use.
_FIELDS: dict[int, tuple] = {}
_FIELDS_MAX = 512


def _array_fields(v, check) -> tuple | None:
    hit = _FIELDS.get(id(v))
    if (
        hit is not None
        and hit[0]() is v
        and hit[1] is check
        and v.shape == hit[2]
        and v.strides == hit[3]
        and v.dtype is hit[4]
    ):
        return hit[5]
    if type(v) is not np.ndarray:
        return None
    dtype, ndim, writable = check
    flags = v.flags
    if (
        v.ndim != ndim
        or v.dtype != dtype
        or not flags.c_contiguous
        or not flags.aligned
        or flags.writeable != writable
    ):
        return None
    # meminfo and parent stay NULL: the kernel only reads and writes the data
    fields = (0, 0, v.size, v.itemsize, v.__array_interface__["data"][0], *v.shape, *v.strides)
    if len(_FIELDS) >= _FIELDS_MAX:
        _FIELDS.clear()
    _FIELDS[id(v)] = (weakref.ref(v), check, v.shape, v.strides, v.dtype, fields)
    return fields


# Python values numba types as each scalar (numba.typeof), by exact type: a bool is not an
# int64 here, an int is not a float64 (each would be another compiled version).
_SCALAR_CHECK = {
    "int64": (int, np.int64),
    "uint64": (np.uint64,),
    "int32": (np.int32,),
    "uint32": (np.uint32,),
    "int16": (np.int16,),
    "uint16": (np.uint16,),
    "int8": (np.int8,),
    "uint8": (np.uint8,),
    "float64": (float, np.float64),
    "float32": (np.float32,),
    "bool": (bool, np.bool_),
}
