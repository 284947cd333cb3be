"""Link cached kernel objects in memory with llvmlite alone (no numba import) and call them.

numba's machine code calls a few of numba's C helpers (``numba_frexp``, array reshapes, the
runtime's ``NRT_*`` functions, error reporting) and CPython's C API. numba gives LLVM their
addresses when it is imported; here the same addresses come from numba's two C extension
modules loaded by file (``_helperlib``, ``core/runtime/_nrt_python``: C code only, without the
numba package's Python import, which is what costs ~0.2 s), from CPython's own symbols
(``ctypes.pythonapi``) and from the C library. Every undefined symbol an object lists
(``elf.undefined_symbols``) is resolved before linking; a kernel with one that cannot be is
left out (LLVM would stop the process on it).

One MCJIT engine per process holds every object loaded; llvmlite's import and the engine's
set-up cost ~20-30 ms, against numba's ~0.25 s.
"""

from __future__ import annotations

import builtins
import ctypes
import importlib.util

from xaml3d.native.store import package_file

_engine = None
_symbols: dict[str, int] | None = None
_libc = None


def engine():
    """The process's MCJIT engine (llvmlite imported and the native target set up once)."""
    global _engine
    if _engine is None:
        import llvmlite.binding as llvm

        llvm.initialize_native_target()
        llvm.initialize_native_asmprinter()
        target = llvm.Target.from_default_triple()
        tm = target.create_target_machine(
            cpu=llvm.get_host_cpu_name(),
            features=llvm.get_host_cpu_features().flatten(),
            reloc="static" if target.name.startswith("x86") else "default",
            codemodel="jitdefault",
        )
        _engine = llvm.create_mcjit_compiler(llvm.parse_assembly(""), tm)
    return _engine


def _extension(package: str, relative: str, name: str):
    """A C extension module of ``package`` loaded from its file, without importing the
    package itself (its C helpers' addresses are all that is needed)."""
    path = package_file(package, relative, extension=True)
    ext = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(ext)
    ext.loader.exec_module(module)
    return module


def _helper_symbols() -> dict[str, int]:
    """numba's C helpers under the names numba gives them in LLVM (``numba.core.base.
    _load_global_helpers``, ``numba.core.runtime.nrt``), and the exception classes."""
    global _symbols
    if _symbols is None:
        table: dict[str, int] = {"_Py_NoneStruct": id(None)}
        helper = _extension("numba", "_helperlib", "numba._helperlib")
        for py_name, address in helper.c_helpers.items():
            table["numba_" + py_name] = address
            table.setdefault(py_name, address)  # the C math functions numba maps by name
        nrt = _extension("numba", "core/runtime/_nrt_python", "numba.core.runtime._nrt_python")
        for py_name, address in nrt.c_helpers.items():
            table[py_name if py_name.startswith("_") else "NRT_" + py_name] = address
        for obj in vars(builtins).values():
            if isinstance(obj, type) and issubclass(obj, BaseException):
                table["PyExc_" + obj.__name__] = id(obj)
        _symbols = table
    return _symbols


def address(name: str) -> int | None:
    """The address numba would give LLVM for an undefined symbol, or None."""
    global _libc
    table = _helper_symbols()
    if name in table:
        return table[name]
    if name.startswith(("Py", "_Py")):
        try:
            return ctypes.cast(getattr(ctypes.pythonapi, name), ctypes.c_void_p).value
        except AttributeError:
            return None
    if _libc is None:
        _libc = ctypes.CDLL(None)
    try:
        return ctypes.cast(getattr(_libc, name), ctypes.c_void_p).value
    except AttributeError:
        return None


def link(objects: list[bytes], undefined: list[str]) -> bool:
    """Give LLVM every undefined symbol's address, then add the objects to the engine; False
    (nothing added) when a symbol has no address."""
    import llvmlite.binding as llvm

    found = {}
    for name in undefined:
        at = address(name)
        if not at:
            return False
        found[name] = at
    ee = engine()
    for name, at in found.items():
        llvm.add_symbol(name, at)
    for data in objects:
        ee.add_object_file(llvm.ObjectFileRef.from_data(data))
    return True


# void trampoline(const i64* block, void* result, i32* status): the GIL is released during the
# call (the kernels are compiled nogil and touch no Python object)
_TRAMPOLINE = ctypes.CFUNCTYPE(None, ctypes.c_char_p, ctypes.c_void_p, ctypes.c_void_p)


def function(symbol: str):
    """The ctypes callable of a linked trampoline (the engine finalised first)."""
    ee = engine()
    ee.finalize_object()
    at = ee.get_function_address(symbol)
    if not at:
        raise LookupError(symbol)
    return _TRAMPOLINE(at)
