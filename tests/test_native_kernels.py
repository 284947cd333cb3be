"""Native loading of the compiled kernels (``xaml3d.native``): numba's cached machine code kept
with a trampoline and linked by llvmlite in a process that never imports numba.

The rules of the argument block (types checked as numba would type them, the flattened array
fields), the trampoline's IR, the object files' undefined symbols; then whole processes: a
small kernel module kept, loaded and called without numba, a damaged object refused and made
again; and the renderer's kernels drawing reference cases natively, bit for bit as numba's
own loading draws them.
"""

from __future__ import annotations

import json
import os
import struct
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from xaml3d.native import abi, elf

ROOT = Path(__file__).resolve().parent.parent
REFERENCE = ROOT / "tests" / "reference"

llvm = pytest.importorskip("llvmlite.binding", reason="llvmlite is not installed")


# ------------------------------------------------------------------ the argument block


def _sig():
    args = [["a", "float32", 2, False], ["a", "float64", 1, True], ["s", "int64"],
            ["s", "float64"], ["s", "bool"], ["s", "float32"]]  # fmt: skip
    return abi.Signature(args, ["tuple", "int64", "float64"])


def test_block_holds_flattened_arrays_and_scalars():
    sig = _sig()
    a = np.zeros((3, 4), np.float32)
    b = np.arange(5.0)
    b.flags.writeable = False
    block = sig.pack((a, b, 7, 2.5, True, np.float32(0.75)))
    assert block is not None and len(block) == 8 * (5 + 4 + 5 + 2 + 4)
    slots = struct.unpack("<QQqqQqqqq" + "QQqqQqq" + "qdq", block[: 8 * 19])
    # meminfo, parent, size, itemsize, data, shape, strides
    assert slots[:9] == (0, 0, 12, 4, a.ctypes.data, 3, 4, 16, 4)
    assert slots[9:16] == (0, 0, 5, 8, b.ctypes.data, 5, 8)
    assert slots[16:] == (7, 2.5, 1)
    assert struct.unpack("<f", block[8 * 19 : 8 * 19 + 4]) == (0.75,)


@pytest.mark.parametrize(
    "change",
    [
        lambda v: (v[0].astype(np.float64), *v[1:]),  # another dtype
        lambda v: (v[0][:, ::2], *v[1:]),  # not contiguous
        lambda v: (v[0][None], *v[1:]),  # another number of dimensions
        lambda v: (v[0], v[1].copy(), *v[2:]),  # writable where read-only was compiled
        lambda v: (v[0], v[1], True, *v[3:]),  # a bool is not an int64
        lambda v: (v[0], v[1], 2**63, *v[3:]),  # beyond int64 (numba: uint64)
        lambda v: (v[0], v[1], v[2], 3, *v[4:]),  # an int is not a float64
        lambda v: (v[0], v[1], v[2], v[3], 1, v[5]),  # an int is not a bool
        lambda v: (v[0], v[1], v[2], v[3], v[4], 0.75),  # a float is not a float32
        lambda v: (*v[:2], list(v[2:])),  # a list
        lambda v: v[:5],  # too few
    ],
)
def test_arguments_numba_would_type_otherwise_are_not_packed(change):
    sig = _sig()
    b = np.arange(5.0)
    b.flags.writeable = False
    values = (np.zeros((3, 4), np.float32), b, 7, 2.5, True, np.float32(0.75))
    assert sig.pack(values) is not None
    assert sig.pack(change(values)) is None


def test_results_and_statuses():
    sig = _sig()
    buf = struct.pack("<qd", -4, 0.5)
    assert sig.result_of(abi.STATUS_VALUE, buf) == (-4, 0.5)
    one = abi.Signature([], ["int64"])
    assert one.result_of(abi.STATUS_VALUE, struct.pack("<q", 9)) == 9
    flag = abi.Signature([], ["bool"])
    assert flag.result_of(abi.STATUS_VALUE, b"\x01" + bytes(7)) is True
    none = abi.Signature([], [])
    assert none.result_of(abi.STATUS_NONE, bytes(8)) is None
    with pytest.raises(abi.KernelRaised, match="status 1"):
        sig.result_of(1, buf)


def test_describe_refuses_what_the_block_cannot_carry():
    from numba import types

    arr = types.Array(types.float64, 2, "C")
    assert abi.describe((arr, types.int64, types.boolean), types.none) == (
        [["a", "float64", 2, False], ["s", "int64"], ["s", "bool"]], [],
    )  # fmt: skip
    for args, res in (
        ((types.Array(types.float64, 2, "A"),), types.none),  # any layout
        ((types.UniTuple(types.int64, 2),), types.none),  # a tuple argument
        ((arr,), arr),  # an array result (allocated by the kernel)
        ((arr,), types.Tuple((types.boolean, types.int64))),
    ):
        with pytest.raises(abi.Unsupported):
            abi.describe(args, res)


def test_trampoline_ir_is_valid_for_every_kind():
    """In the pointer form the installed LLVM parses (``abi.typed_pointers``): LLVM 14 knows
    typed pointers only, LLVM 17 on opaque ones only."""
    args = [["a", "uint8", 3, False], ["s", "int64"], ["s", "float64"], ["s", "float32"],
            ["s", "bool"]]  # fmt: skip
    typed = abi.typed_pointers()
    ir = abi.trampoline_ir("tramp", "kernel", args, llvm.get_process_triple(), "", typed=typed)
    assert ("ptr" in ir.split()) is not typed and ("i64*" in ir) is typed
    mod = llvm.parse_assembly(ir)
    mod.verify()
    fn = mod.get_function("tramp")
    want = ["i64*", "i8*", "i32*"] if typed else ["ptr", "ptr", "ptr"]
    assert [str(a.type) for a in fn.arguments] == want
    assert len(list(mod.get_function("kernel").arguments)) == 2 + 11 + 4


def test_pointer_form_follows_the_llvm_version():
    import llvmlite

    major = llvm.llvm_version_info[0]
    if major < 15:
        assert abi.typed_pointers()
    elif major >= 17:
        assert not abi.typed_pointers()
    else:  # llvmlite 0.44 (LLVM 15): typed unless it turned opaque pointers on
        assert abi.typed_pointers() is not llvmlite.opaque_pointers_enabled


def test_undefined_symbols_of_an_object():
    llvm.initialize_native_target()
    llvm.initialize_native_asmprinter()
    ir = textwrap.dedent(f"""
        target triple = "{llvm.get_process_triple()}"
        declare double @external_one(double)
        @external_data = external global i64
        define double @here(double %x) {{
          %v = load i64, {"i64*" if abi.typed_pointers() else "ptr"} @external_data
          %d = sitofp i64 %v to double
          %r = call double @external_one(double %d)
          ret double %r
        }}
    """)
    tm = llvm.Target.from_default_triple().create_target_machine()
    obj = tm.emit_object(llvm.parse_assembly(ir))
    if not obj.startswith(b"\x7fELF"):
        pytest.skip("this platform's objects are not ELF (the kernels stay on numba there)")
    assert elf.undefined_symbols(obj) == ["external_data", "external_one"]
    with pytest.raises(ValueError):
        elf.undefined_symbols(b"MZ not an ELF object")


# ------------------------------------------------------------------ whole processes

_KERNELS = """
import numba
import numpy as np

SCALE = 3

@numba.njit(cache=True, nogil=True)
def axpy(a, x, y, out, flip):
    n = 0
    for i in range(x.shape[0]):
        out[i] = (a * x[i] + y[i]) * (-1.0 if flip else 1.0)
        if out[i] > 0:
            n += 1
    return n, out.shape[0]

@numba.njit(cache=True, nogil=True)
def grid(out):
    scratch = np.zeros(out.shape[1])  # the runtime's allocation, freed on return
    for r in range(out.shape[0]):
        for c in range(out.shape[1]):
            scratch[c] += r
            out[r, c] = scratch[c] * SCALE
"""

_CALL = """
import json, sys
import numpy as np
from xaml3d import native
k = native.kernels("probe_kernels")
x = np.arange(6.0); y = np.ones(6); out = np.empty(6)
first = k.axpy(2.0, x, y, out, True)
g = np.empty((3, 4)); k.grid(g)
# a float32 vector is another compiled version: numba's dispatch takes it
x32 = np.arange(6, dtype=np.float32); out2 = np.empty(6)
second = k.axpy(2.0, x32, y, out2, False)
# the first arguments packed once for a loop; the rest per call
bound = native.bind(k.axpy, 2.0, x, y)
loop = [list(bound(np.empty(6), flip)) for flip in (False, True, False)]
o3 = np.empty(6); bound(o3, True)
print(json.dumps({"first": list(first), "out": out.tolist(), "grid": g.tolist(),
                  "second": list(second), "out2": out2.tolist(), "SCALE": k.SCALE,
                  "loop": loop, "o3": o3.tolist(),
                  "native": k.native_kernels, "through_numba": sorted(k.numba_kernels),
                  "numba": "numba" in sys.modules}))
"""


def _run(code: str, env: dict, cwd: Path) -> dict:
    proc = subprocess.run(
        [sys.executable, "-c", code], env=env, cwd=cwd, capture_output=True, text=True,
        timeout=300,
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    return json.loads(proc.stdout.strip().splitlines()[-1])


def test_a_kernel_module_is_kept_then_called_without_numba(tmp_path):
    (tmp_path / "probe_kernels.py").write_text(_KERNELS)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), XAML3D_NATIVE="1",
               PYTHONPATH=f"{tmp_path}{os.pathsep}{ROOT}")  # fmt: skip
    want_out = [-(2.0 * i + 1.0) for i in range(6)]
    want_grid = [[3.0 * sum(range(r + 1))] * 4 for r in range(3)]
    # first process: no native code yet, numba runs the kernels and they are kept
    a = _run(_CALL, env, tmp_path)
    assert a["numba"] and a["native"] == []
    assert a["through_numba"] == ["axpy", "grid"]
    # next process: the kept machine code, without numba, for both versions of axpy
    b = _run(_CALL, env, tmp_path)
    assert not b["numba"], "numba was imported"
    assert b["native"] == ["axpy", "grid"] and b["through_numba"] == []
    for r in (a, b):
        assert r["first"] == [0, 6] and r["out"] == want_out and r["grid"] == want_grid
        assert r["second"] == [6, 6] and r["out2"] == [2.0 * i + 1.0 for i in range(6)]
        assert r["SCALE"] == 3
        assert r["loop"] == [[6, 6], [0, 6], [6, 6]] and r["o3"] == want_out
    # a damaged object is not linked (LLVM would stop the process): numba runs that kernel,
    # and keeps it again for the next process
    (folder,) = (tmp_path / "cache" / "native").glob("probe_kernels-*")
    manifest = json.loads((folder / "manifest.json").read_text())
    obj = folder / manifest["kernels"]["grid"][0]["objects"][0]
    data = bytearray(obj.read_bytes())
    data[len(data) // 2] ^= 0xFF
    obj.write_bytes(bytes(data))
    c = _run(_CALL, env, tmp_path)
    assert c["native"] == ["axpy"] and c["through_numba"] == ["grid"]
    assert c["grid"] == want_grid
    d = _run(_CALL, env, tmp_path)
    assert d["native"] == ["axpy", "grid"] and not d["numba"]
    # turned off: numba's own loading
    e = _run(_CALL, dict(env, XAML3D_NATIVE="0"), tmp_path)
    assert e["numba"] and e["native"] == [] and e["grid"] == want_grid


def test_the_first_run_on_a_machine_says_it_prepares_the_kernels(tmp_path):
    """Told once, on stderr, when a kernel module with nothing kept on this machine goes to
    numba (the command line sets ``native.notify``); not again once it is kept."""
    (tmp_path / "probe_kernels.py").write_text(_KERNELS)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), XAML3D_NATIVE="1",
               PYTHONPATH=f"{tmp_path}{os.pathsep}{ROOT}")  # fmt: skip
    code = "import sys; from xaml3d import native; native.notify = print\n" + _CALL

    def run() -> str:
        proc = subprocess.run([sys.executable, "-c", code], env=env, cwd=tmp_path,
                              capture_output=True, text=True, timeout=300)  # fmt: skip
        assert proc.returncode == 0, proc.stderr
        return proc.stdout

    from xaml3d import native

    first = run()
    assert first.count(native.FIRST_TIME) == 1
    assert native.FIRST_TIME not in run()


def test_a_new_source_is_a_new_key_and_old_folders_go_beyond_a_few(tmp_path, monkeypatch):
    from xaml3d.native import store

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"), XAML3D_NATIVE="1",
               PYTHONPATH=f"{tmp_path}{os.pathsep}{ROOT}")  # fmt: skip
    native = tmp_path / "cache" / "native"
    (tmp_path / "probe_kernels.py").write_text(_KERNELS)
    _run(_CALL, env, tmp_path)
    (first,) = native.glob("probe_kernels-*")
    (tmp_path / "probe_kernels.py").write_text(_KERNELS.replace("SCALE = 3", "SCALE = 4"))
    r = _run(_CALL, env, tmp_path)
    assert r["native"] == [] and r["SCALE"] == 4  # the old code is not used
    # another install sharing the cache keeps its folder: the last used few are kept
    assert len(list(native.glob("probe_kernels-*"))) == 2 and first.exists()
    for k in range(store.KEEP_OTHERS + 2):  # more keys than are kept: the oldest go first
        old = native / f"probe_kernels-old{k}"
        old.mkdir()
        (old / "manifest.json").write_text("{}")
        os.utime(old / "manifest.json", (1000 + k, 1000 + k))
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "cache"))
    store.prune("probe_kernels", "none")
    kept = sorted(p.name for p in native.glob("probe_kernels-*"))
    assert len(kept) == store.KEEP_OTHERS
    assert "probe_kernels-old0" not in kept and first.name in kept


def test_native_modules_do_not_import_numba():
    code = (
        "import sys; import xaml3d.native, xaml3d.native.engine, xaml3d.native.abi, "
        "xaml3d.native.store, xaml3d.native.elf; from xaml3d.native import engine; "
        "engine.engine(); engine.address('numba_frexp'); print('numba' in sys.modules)"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip() == "False"


_CASES = sorted(
    p
    for folder in ("brush", "material", "blend", "light", "mesh", "clip")
    for p in (REFERENCE / folder).glob("*.xaml")
)


def test_reference_cases_draw_the_same_natively_without_numba(tmp_path):
    """The renderer's kernels natively, bit for bit as numba's own loading draws them: the
    reference cases of brushes, materials, blending, lights, meshes and clipping, each at the
    default anti-aliasing, flat mode and ssaa 2."""
    env = dict(os.environ, XAML3D_KERNELS="auto", PYTHONPATH=str(ROOT))
    probe = [sys.executable, str(ROOT / "tests" / "_native_probe.py"), *map(str, _CASES)]

    def run(native: str) -> dict:
        proc = subprocess.run(probe, env=dict(env, XAML3D_NATIVE=native), capture_output=True,
                              text=True, timeout=600, cwd=tmp_path)  # fmt: skip
        assert proc.returncode == 0, proc.stderr
        return json.loads(proc.stdout)

    numba_own = run("0")
    run("1")  # keeps what was not kept yet
    native = run("1")
    assert not native["numba_imported"], native["through_numba"]
    assert {"draw_pass", "resolve", "blend_rows", "shade_rows"} <= set(native["native"])
    assert native["drawn"] == numba_own["drawn"]
    assert len(numba_own["drawn"]) == 3 * len(_CASES)


def test_an_animation_draws_the_same_natively_without_numba(tmp_path):
    """An animation's frames (frame sessions: colour blocks, resolve passes, facing) and its
    GIF (the compiled GIF passes) natively, the same frames and bytes as numba's loading."""
    env = dict(os.environ, XAML3D_KERNELS="auto", PYTHONPATH=str(ROOT))
    scene = ROOT / "samples" / "spinning-cube.xaml"

    def run(native: str) -> tuple[dict, bytes]:
        gif = tmp_path / f"spin-{native}.gif"
        probe = [sys.executable, str(ROOT / "tests" / "_native_probe.py"), "--animate",
                 str(scene), str(gif)]  # fmt: skip
        proc = subprocess.run(probe, env=dict(env, XAML3D_NATIVE=native), capture_output=True,
                              text=True, timeout=600, cwd=tmp_path)  # fmt: skip
        assert proc.returncode == 0, proc.stderr
        return json.loads(proc.stdout), gif.read_bytes()

    numba_own, gif0 = run("0")
    run("1")
    native, gif1 = run("1")
    assert not native["numba_imported"], native["through_numba"]
    assert native["drawn"] == numba_own["drawn"] and len(native["drawn"]) == 30
    assert gif1 == gif0
