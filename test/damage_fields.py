#!/usr/bin/python3
"""Damages one step of a fields.h5 the way a kill while HDF5 wrote it can: the object header of the
step's group overwritten, so that HDF5 can no longer read the group nor remove its link (docs/scenes.md,
"Checkpoint and restart").

  damage_fields.py FIELDS_H5 STEP

Exits non-zero if the step is not there, or if HDF5 still reads its group after the damage (the test
using it would then not test a damaged step).
"""
import sys

import h5py
import h5py.h5o


def main():
    path, step = sys.argv[1], int(sys.argv[2])
    name = f"/steps/{step:06d}"
    with h5py.File(path, "r") as f:
        if name not in f:
            sys.exit(f"damage_fields: {path} has no {name}")
        addr = h5py.h5o.get_info(f[name].id).addr
    with open(path, "r+b") as raw:  # the header's signature, version and flags: unreadable
        raw.seek(addr)
        raw.write(b"\0" * 16)
    try:
        with h5py.File(path, "r") as f:
            list(f[name].attrs)
    except Exception as e:  # what the restart will meet
        print(f"damage_fields: {name} of {path} damaged at byte {addr} ({type(e).__name__})")
        return 0
    sys.exit(f"damage_fields: {name} of {path} is still readable after the damage")


if __name__ == "__main__":
    sys.exit(main())
