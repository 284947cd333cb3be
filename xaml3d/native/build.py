"""Keep a kernel's machine code where a process without numba can load it (numba side).

Called in a process that has numba imported and has just run a kernel through numba's own
dispatch (compiled, or loaded from numba's cache): for each compiled version of the kernel, the
same machine code numba caches (``serialize_using_object_code``: the kernel and what it calls,
linked in one object) is written beside a small trampoline object (``abi.trampoline_ir``)
and listed in the module's manifest (``store``). Nothing is compiled again: the next process
loads exactly the code numba would have loaded, without importing numba.

Everything here is best effort: a kernel whose types the ABI does not carry, an object format
other than ELF, a cache folder that cannot be written, all leave the kernel on numba, silently.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from xaml3d.native import abi, elf, store

_done: set[tuple[str, str, str]] = set()  # (module, kernel, signature) saved by this process


def remember(module, names: list[str]) -> None:
    """Save the compiled versions of ``module``'s kernels ``names`` (numba dispatchers that
    have run in this process) that the manifest does not list yet."""
    import xaml3d.native as native

    if not native.enabled():
        return
    try:
        _remember(module, names)
    except Exception:  # noqa: BLE001 - a cache that cannot be written costs speed, not results
        return


def _remember(module, names: list[str]) -> None:
    import llvmlite.binding as llvm

    source = Path(module.__file__)
    cpu, features = llvm.get_host_cpu_name(), llvm.get_host_cpu_features().flatten()
    k = store.key(source, cpu, features)
    where = store.folder(module.__name__, k)
    manifest = store.read_manifest(where) or {
        "format": store.FORMAT, "module": module.__name__, "kernels": {}, "constants": {},
    }  # fmt: skip
    manifest["constants"] = _constants(module)
    manifest["dispatchers"] = sorted(
        name for name, value in vars(module).items() if _is_dispatcher(value)
    )
    changed = False
    for name in names:
        dispatcher = getattr(module, name, None)
        for sig in list(getattr(dispatcher, "signatures", ())):
            tag = (module.__name__, name, str(sig))
            if tag in _done:
                continue
            _done.add(tag)
            versions = manifest["kernels"].setdefault(name, [])
            if any(v["numba"] == str(sig) and _intact(where, v) for v in versions):
                continue
            # a version whose files are gone or damaged is made again
            versions[:] = [v for v in versions if v["numba"] != str(sig)]
            if not dispatcher.targetoptions.get("nogil"):
                continue  # the trampoline is called with the GIL released
            try:
                entry = _save(where, name, _free_index(versions), dispatcher, sig)
            except (abi.Unsupported, ValueError, AttributeError, KeyError):
                continue
            versions.append(entry)
            changed = True
    if changed:
        store.write_atomically(where / "manifest.json", json.dumps(manifest, indent=1).encode())
        store.prune(module.__name__, k)


def _is_dispatcher(value) -> bool:
    return hasattr(value, "py_func") and hasattr(value, "signatures")


def _intact(where: Path, entry: dict) -> bool:
    try:
        data = [(where / f).read_bytes() for f in entry["objects"]]
    except (OSError, KeyError, TypeError):
        return False
    return [hashlib.sha256(b).hexdigest() for b in data] == entry.get("sha256")


def _free_index(versions: list) -> int:
    used = {v.get("symbol") for v in versions}
    k = 0
    while any(str(s).endswith(f"_{k}") for s in used):
        k += 1
    return k


def _constants(module) -> dict:
    """The module's integer and float constants (``PER_PIXEL``...), which callers read from the
    kernels module: the native library serves them without importing it."""
    out = {}
    for name, value in vars(module).items():
        if name.isupper() and type(value) in (int, float, bool):
            out[name] = value
    return out


def _save(where: Path, name: str, index: int, dispatcher, sig) -> dict:
    cres = dispatcher.overloads[sig]
    args, result = abi.describe(sig, cres.signature.return_type)
    # the flattened argument types numba really uses must be the ones the trampoline passes
    packer = dispatcher.targetctx.get_arg_packer(sig)
    if [_llvm_name(str(t)) for t in packer.argument_types] != abi.llvm_types(args):
        raise abi.Unsupported(f"{name}: argument layout")
    native = cres.fndesc.mangled_name
    code = _cached_object(dispatcher, sig)
    undefined = elf.undefined_symbols(code)
    symbol = f"xaml3d_native_{name}_{index}"
    tm = cres.library.codegen._tm
    call = _trampoline_object(tm, symbol, native, args)
    files = [f"{name}-{index}.o", f"{name}-{index}-call.o"]
    store.write_atomically(where / files[0], code)
    store.write_atomically(where / files[1], call)
    undefined = sorted(set(undefined) | set(elf.undefined_symbols(call)) - {native})
    return {
        "numba": str(sig), "args": args, "result": result, "symbol": symbol,
        "objects": files, "sha256": [hashlib.sha256(b).hexdigest() for b in (code, call)],
        "undefined": undefined,
    }  # fmt: skip


def _trampoline_object(tm, symbol: str, native: str, args: list) -> bytes:
    """The trampoline's object code, its IR in the pointer form the installed LLVM parses
    (``abi.typed_pointers``; the other form if that one is refused). What LLVM prints on the
    way goes to the debug log (``quiet``), never to the user's terminal."""
    import llvmlite.binding as llvm

    from xaml3d.native import quiet

    typed = abi.typed_pointers()
    triple, layout = llvm.get_process_triple(), str(tm.target_data)
    with quiet.llvm_output():
        for form in (typed, not typed):
            try:
                mod = llvm.parse_assembly(abi.trampoline_ir(symbol, native, args, triple, layout,
                                                            typed=form))  # fmt: skip
                mod.verify()
            except RuntimeError:
                continue
            return tm.emit_object(mod)
    raise ValueError(f"{symbol}: LLVM parses neither pointer form")


def _cached_object(dispatcher, sig) -> bytes:
    """The object code numba's on-disk cache holds for this version (its index key, then
    the saved compile result, whose first part is the library as (name, 'object', (object
    code, bitcode))): a library loaded from the cache keeps no object code in memory."""
    cache = dispatcher._cache
    payload = cache._cache_file.load(cache._index_key(sig, dispatcher.targetctx.codegen()))
    if payload is None:
        raise ValueError("not in numba's cache")
    _, kind, data = payload[0]
    if kind != "object":
        raise ValueError(kind)
    return data[0]


def _llvm_name(t: str) -> str:
    # numba's IR builder spells pointers with their pointee (``i8*``); LLVM's are opaque
    return "ptr" if t.endswith("*") else t
