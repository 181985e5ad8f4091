#!/usr/bin/python3
"""Damaged copies of a checkpoint, for the tests that a restart refuses them (docs/scenes.md,
"Checkpoint and restart").

  damage_checkpoint.py CHECKPOINT OUTDIR

writes into OUTDIR:
  truncated.h5  the first half of the file (a copy cut short);
  data.h5       one byte of the /solution array changed (HDF5 keeps no checksum of raw data: only
                boltnet's checksum of the arrays can tell);
  scalars.h5    one character of the data_checksum attribute changed (boltnet's checksum of the
                scalars must tell);
and checks that each differs from the original where it says.
"""
import os
import sys

import h5py


def main():
    src, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    data = bytearray(open(src, "rb").read())
    with open(os.path.join(out, "truncated.h5"), "wb") as f:
        f.write(data[: len(data) // 2])

    with h5py.File(src, "r") as h:
        sol = h["solution"].id  # PETSc writes its vectors in chunks, unfiltered
        if sol.get_offset() is not None:
            offset, nbytes = sol.get_offset(), sol.get_storage_size()
        else:
            info = sol.get_chunk_info(0)
            assert info.filter_mask == 0 and info.size >= 16, "the first chunk of /solution is filtered or empty"
            offset, nbytes = info.byte_offset, info.size
        checksum = bytes(h.attrs["data_checksum"])
    d = bytearray(data)
    d[offset + nbytes - 2] ^= 0x10  # a high byte of the last value: its exponent changes
    open(os.path.join(out, "data.h5"), "wb").write(d)

    at = data.find(checksum)
    assert at >= 0 and data.find(checksum, at + 1) < 0, "the data_checksum value is not found once in the file"
    s = bytearray(data)
    s[at] = ord("0") if s[at] != ord("0") else ord("1")
    open(os.path.join(out, "scalars.h5"), "wb").write(s)
    print(f"damage_checkpoint: {len(data)} bytes; solution at {offset} ({nbytes} bytes); data_checksum at {at}")


if __name__ == "__main__":
    main()
