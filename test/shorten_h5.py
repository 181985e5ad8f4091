#!/usr/bin/python3
"""Leaves an HDF5 file the way a kill can: shorter than the end of file its superblock records (HDF5
had allocated and recorded space for data that never reached the disk; it then refuses the file:
"truncated file"). The superblock's end-of-file address is moved BYTES past the file's end (versions
0 and 1 of the superblock, which have no checksum; PETSc's HDF5 viewer and h5py write version 0).

  shorten_h5.py FILE [BYTES]     (BYTES default 328, as measured on a fields.h5 left by a kill)

Exits non-zero if the superblock is not at byte 0 or not of version 0 or 1, or if HDF5 still opens
the file afterwards (the test using it would then not test a short file).
"""
import os
import struct
import sys

import h5py


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    path, extra = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 328
    size = os.path.getsize(path)
    with open(path, "r+b") as f:
        b = f.read(64)
        if b[:8] != b"\x89HDF\r\n\x1a\n" or b[8] > 1:
            sys.exit(f"shorten_h5: {path} has no superblock of version 0 or 1 at byte 0")
        offsets = b[13]
        at = (24 if b[8] == 0 else 28) + 2 * offsets  # the base address, the free-space address, then the end of file
        fmt = {4: "<I", 8: "<Q"}[offsets]
        base = struct.unpack(fmt, b[at - 2 * offsets: at - offsets])[0]
        f.seek(at)
        f.write(struct.pack(fmt, size - base + extra))
    try:
        h5py.File(path, "r").close()
    except OSError as e:  # what the restart will meet
        print(f"shorten_h5: {path} now {extra} bytes short of its superblock's end ({e})")
        return 0
    sys.exit(f"shorten_h5: HDF5 still opens {path}")


if __name__ == "__main__":
    sys.exit(main())
