"""The undefined symbols of an ELF64 object file (the machine code numba caches on Linux).

Each must be given an address before the object is linked in memory (``native.engine``): LLVM
stops the whole process on a symbol it cannot resolve, so the loader resolves every name listed
here first, and leaves a kernel on numba when one is missing.
"""

from __future__ import annotations

import struct

_SHT_SYMTAB = 2


def undefined_symbols(data: bytes) -> list[str]:
    """Names of the undefined symbols of a little-endian ELF64 object; ValueError when the
    data is not one (another platform's object format: the kernels stay on numba there)."""
    if data[:4] != b"\x7fELF" or data[4] != 2 or data[5] != 1:
        raise ValueError("not a little-endian ELF64 object")
    shoff = struct.unpack_from("<Q", data, 0x28)[0]
    shentsize, shnum = struct.unpack_from("<HH", data, 0x3A)
    sections = [
        struct.unpack_from("<IIQQQQIIQQ", data, shoff + k * shentsize) for k in range(shnum)
    ]
    names = []
    for sh in sections:
        if sh[1] != _SHT_SYMTAB:
            continue
        offset, size, link, entsize = sh[4], sh[5], sh[6], sh[9] or 24
        strtab = sections[link]
        str_off = strtab[4]
        for pos in range(offset + entsize, offset + size, entsize):  # entry 0 is the null symbol
            st_name, _info, _other, st_shndx = struct.unpack_from("<IBBH", data, pos)
            if st_shndx != 0 or st_name == 0:
                continue
            end = data.index(b"\0", str_off + st_name)
            names.append(data[str_off + st_name : end].decode())
    return sorted(set(names))
