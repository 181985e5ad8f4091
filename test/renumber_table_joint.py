#!/usr/bin/python3
"""Gives the last row of a joints.h5 a joint id the model does not have (one past the largest), as a
table written for another model would: a restart must refuse to continue it (docs/output.md, "The
joint table"). On several ranks the last row is read by the last rank that holds rows, so the test
also shows that a complaint found by one rank stops every rank.

  renumber_table_joint.py JOINTS_H5

Exits non-zero if the file has no joint dataset or no row.
"""
import sys

import h5py


def main():
    path = sys.argv[1]
    with h5py.File(path, "r+") as f:
        if "joint" not in f or f["joint"].shape[0] == 0:
            sys.exit(f"renumber_table_joint: {path} has no joint rows")
        ids = f["joint"]
        old = int(ids[-1])
        ids[-1] = int(ids[:].max()) + 1
        print(f"{path}: the last row's joint {old} is now {int(ids[-1])}")


if __name__ == "__main__":
    main()
