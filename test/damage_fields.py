#!/usr/bin/python3
"""Damages an HDF5 output file the way a kill can (docs/scenes.md, "Checkpoint and restart").

  damage_fields.py FIELDS_H5 STEP       the object header of the step's group overwritten, so that
                                        HDF5 can no longer read the group nor remove its link
  damage_fields.py --short FILE [BYTES] the superblock's end of file moved BYTES (default 328, as
                                        measured on a fields.h5 left by a kill) past the file's end:
                                        HDF5 had allocated and recorded space for data that never
                                        reached the disk, and refuses the file ("truncated file")

--short takes superblocks of version 0 and 1 (no checksum; PETSc's HDF5 viewer and h5py write
version 0) at byte 0. Exits non-zero if the step or the superblock is not there, or if HDF5 still
reads what was damaged (the test using it would then not test a damaged file).
"""
import os
import struct
import sys

import h5py
import h5py.h5o


def refused(read, what):
    """0 if read() fails as the restart will meet it, else exit: the damage did not take."""
    try:
        read()
    except Exception as e:
        print(f"damage_fields: {what} ({type(e).__name__}: {e})")
        return 0
    sys.exit(f"damage_fields: HDF5 still reads it after the damage: {what}")


def damage_step(path, step):
    name = f"/steps/{step:06d}"
    with h5py.File(path, "r") as f:
        if name not in f:
            sys.exit(f"damage_fields: {path} has no {name}")
        addr = h5py.h5o.get_info(f[name].id).addr
    with open(path, "r+b") as raw:  # the header's signature, version and flags: unreadable
        raw.seek(addr)
        raw.write(b"\0" * 16)

    def read():
        with h5py.File(path, "r") as f:
            list(f[name].attrs)
    return refused(read, f"{name} of {path} damaged at byte {addr}")


def shorten(path, extra):
    size = os.path.getsize(path)
    with open(path, "r+b") as f:
        b = f.read(64)
        if b[:8] != b"\x89HDF\r\n\x1a\n" or b[8] > 1:
            sys.exit(f"damage_fields: {path} has no superblock of version 0 or 1 at byte 0")
        offsets = b[13]
        at = (24 if b[8] == 0 else 28) + 2 * offsets  # the base address, the free-space address, then the end of file
        fmt = {4: "<I", 8: "<Q"}[offsets]
        base = struct.unpack(fmt, b[at - 2 * offsets: at - offsets])[0]
        f.seek(at)
        f.write(struct.pack(fmt, size - base + extra))
    return refused(lambda: h5py.File(path, "r").close(), f"{path} now {extra} bytes short of its superblock's end")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    if sys.argv[1] == "--short":
        return shorten(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 328)
    return damage_step(sys.argv[1], int(sys.argv[2]))


if __name__ == "__main__":
    sys.exit(main())
