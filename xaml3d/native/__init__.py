"""Compiled kernels without numba's start-up: numba's cached machine code, loaded by llvmlite.

numba compiles xaml3d's kernels (``xaml3d.render.kernels``...) once and caches their machine
code on disk, but every process that wants to run them pays numba's import and runtime set-up
first, about 0.25-0.3 s here: more than a whole small render. This package keeps, beside
numba's cache, the same machine code with a small trampoline per kernel (``build``, run in a
process that has numba and has just used the kernel), and loads it later with llvmlite alone
(``engine``, ~30 ms). The code run is byte for byte the code numba would run, so pictures are
the same; the first process on a machine (or after the kernels' source, numba, llvmlite or the
processor changes: ``store.key``) runs them through numba and leaves the native objects for
the next.

``kernels(name)`` gives a stand-in for a kernel module: its kernels that have native code are
called through it (each call's arguments checked against the compiled versions' types, as
numba's dispatch would; anything else goes to numba), its constants are served from the
manifest, and every other attribute imports the real module (and numba) on first use.
``XAML3D_NATIVE=0`` turns this off (always numba's own loading).
"""

from __future__ import annotations

import ctypes
import functools
import hashlib
import importlib
import importlib.util
import os
import sys
from pathlib import Path

ENV = "XAML3D_NATIVE"


def enabled() -> bool:
    """Not turned off (``XAML3D_NATIVE=0``) and on a platform this was checked on: Linux on
    x86-64 (numba links its code with other relocation models and memory managers elsewhere;
    there the kernels keep numba's own loading)."""
    if os.environ.get(ENV, "1").strip().lower() in ("0", "no", "off", "false"):
        return False
    return sys.platform.startswith("linux") and os.uname().machine.lower() in ("x86_64", "amd64")


class Kernels:
    """A kernel module's stand-in (see the package's docstring)."""

    def __init__(
        self, name: str, native: dict | None = None, constants: dict | None = None,
        kernels: list | None = None,
    ):  # fmt: skip
        self._name = name
        self._module = None
        self.native_kernels = sorted(native or ())
        self.numba_kernels: set[str] = set()  # the kernels this process ran through numba
        for kernel in kernels or ():  # known kernels without native code: numba when called
            setattr(self, kernel, _NativeKernel(self, kernel, []))
        for kernel, versions in (native or {}).items():
            setattr(self, kernel, _NativeKernel(self, kernel, versions))
        for key, value in (constants or {}).items():
            setattr(self, key, value)

    def real(self):
        """The real kernel module (importing it imports numba)."""
        if self._module is None:
            if notify is not None and not kept(self._name):
                _first_time()
            self._module = importlib.import_module(self._name)
        return self._module

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        value = getattr(self.real(), name)
        if hasattr(value, "py_func") and hasattr(value, "signatures"):
            value = _Remembering(self, name, value)
        setattr(self, name, value)
        return value


class _Remembering:
    """A numba kernel called through the stand-in: after a call that compiled (or loaded) a
    new version, its machine code is kept for the next process (``build.remember``)."""

    def __init__(self, owner: Kernels, name: str, dispatcher):
        self._owner = owner
        self._name = name
        self._dispatcher = dispatcher
        self._seen = -1

    def __call__(self, *args):
        self._owner.numba_kernels.add(self._name)
        result = self._dispatcher(*args)
        count = len(self._dispatcher.signatures)
        if count != self._seen:
            self._seen = count
            from xaml3d.native import build

            build.remember(self._owner.real(), [self._name])
        return result

    def __getattr__(self, name):
        return getattr(self._dispatcher, name)


class _NativeKernel:
    """A kernel with native code: each call goes to the first compiled version whose types
    match the arguments; none matching, to numba (which may compile another version)."""

    def __init__(self, owner: Kernels, name: str, versions: list):
        self._owner = owner
        self._name = name
        self._versions = versions  # [(abi.Signature, ctypes function)]
        self._numba = None

    def __call__(self, *args):
        for sig, fn in self._versions:
            block = sig.pack(args)
            if block is not None:
                return _run(sig, fn, block)
        return self._through_numba(*args)

    def _through_numba(self, *args):
        if self._numba is None:
            dispatcher = getattr(self._owner.real(), self._name)
            self._numba = _Remembering(self._owner, self._name, dispatcher)
        return self._numba(*args)

    def bind(self, *fixed):
        """The kernel with its first arguments given once (``bind``): their part of the block
        is packed at the first call and reused, so a loop calling the kernel with the same
        arrays and a few changing values (a frame's bands) packs only those."""
        n = len(fixed)
        chosen = []

        def call(*rest):
            if chosen:
                sig, fn, head, tail = chosen[0]
                block = tail.pack(rest)
                if block is not None:
                    return _run(sig, fn, head + block)
            else:
                args = fixed + rest
                for sig, fn in self._versions:
                    block = sig.pack(args)
                    if block is not None:
                        chosen.append((sig, fn, block[: sig.head_size(n)], sig.tail(n)))
                        return _run(sig, fn, block)
            return self._through_numba(*fixed, *rest)

        return call


def _run(sig, fn, block: bytes):
    result = ctypes.create_string_buffer(sig.rsize)
    status = ctypes.c_int32(0)
    fn(block, result, ctypes.byref(status))
    return sig.result_of(status.value, result)


def bind(kernel, *fixed):
    """``kernel`` with its first arguments ``fixed`` (which must not change while the result is
    used): a native kernel packs them once (``_NativeKernel.bind``); any other callable (numba's
    dispatcher) is ``functools.partial``."""
    if isinstance(kernel, _NativeKernel):
        return kernel.bind(*fixed)
    return functools.partial(kernel, *fixed)


_stand_ins: dict[str, Kernels] = {}

# Told once per process (the command line sets it: a line on stderr) when a kernel module with
# no native code kept on this machine goes to numba: the first run on a machine (or after an
# upgrade) compiles the kernels, which takes seconds where later runs take milliseconds.
notify = None
FIRST_TIME = (
    "note: preparing xaml3d's compiled kernels for this machine (the first run only: numba "
    "compiles them, 10-60 s; later runs load them at once)"
)
_notified: list = []


def _first_time() -> None:
    if not _notified:
        _notified.append(True)
        notify(FIRST_TIME)


def kept(name: str) -> bool:
    """Whether this machine kept native code for kernel module ``name`` (a folder of it in the
    cache, whatever its key): a cheap hint, no llvmlite import."""
    found = _kept.get(name)
    if found is None:
        from xaml3d.native import store

        try:
            found = any(store.folder(name, "").parent.glob(f"{name}-*"))
        except OSError:
            found = False
        _kept[name] = found
    return found


_kept: dict[str, bool] = {}


def linked() -> bool:
    """Whether this process has linked native machine code (llvmlite loaded, the engine up)."""
    return any(k.native_kernels for k in _stand_ins.values())


def kernels(name: str) -> Kernels:
    """The stand-in of kernel module ``name`` with whatever native code this machine has for
    it (none: every kernel goes through numba, and is kept as it is used); one per process
    (an object is linked into the process once)."""
    found = _stand_ins.get(name)
    if found is not None:
        return found
    if not enabled():
        found = Kernels(name)
    else:
        try:
            native, constants, names = _load(name)
        except Exception:  # noqa: BLE001 - no native code (no llvmlite, a damaged cache): numba
            native, constants, names = {}, {}, []
        found = Kernels(name, native, constants, names)
    _stand_ins[name] = found
    return found


def _load(name: str) -> tuple[dict, dict, list]:
    from xaml3d.native import abi, engine, quiet, store

    spec = importlib.util.find_spec(name)
    if spec is None or not spec.origin:
        return {}, {}, []
    import llvmlite.binding as llvm

    k = store.key(
        Path(spec.origin), llvm.get_host_cpu_name(), llvm.get_host_cpu_features().flatten()
    )
    where = store.folder(name, k)
    manifest = store.read_manifest(where)
    if manifest is None:
        return {}, {}, []
    linked = []
    native: dict[str, list] = {}
    with quiet.llvm_output():  # whatever LLVM says while linking goes to the debug log
        for kernel, versions in manifest.get("kernels", {}).items():
            for entry in versions:
                try:
                    objects = [(where / f).read_bytes() for f in entry["objects"]]
                except OSError:
                    continue
                # a damaged object would stop the process inside LLVM: check it is what was kept
                if [hashlib.sha256(b).hexdigest() for b in objects] != entry.get("sha256"):
                    continue
                if engine.link(objects, entry["undefined"]):
                    linked.append((kernel, entry))
        for kernel, entry in linked:
            fn = engine.function(entry["symbol"])
            sig = abi.Signature(entry["args"], entry["result"])
            native.setdefault(kernel, []).append((sig, fn))
    if not native:
        return {}, {}, []
    store.touch(where)
    return native, manifest.get("constants", {}), manifest.get("dispatchers", [])
