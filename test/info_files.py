"""PETSc's -info lines of an MPI run, read from one file per rank.

Under mpirun each rank's stdout is a pipe, block-buffered by the C library, and mpirun forwards
whatever each rank has written in the order it arrives: a line of one rank can be cut in two by a
block of another ("[0] ... Using internal PETSc c[1] ... Received 2 ..."), and a checker reading
stdout then misses both. PETSc writes -info to a file per rank instead when given a name,
-info NAME[:classes], as NAME.r (PetscInfoSetFile). run() removes those files before the run, so
that none left by an earlier one is read, and returns what each rank wrote, in rank order.
"""
import glob
import os
import re
import subprocess


def run(command, prefix):
    """Runs command (which must pass -info prefix[:...]); returns (exit code, its stdout and stderr,
    the text of prefix.0, prefix.1, ... joined in rank order)."""
    for stale in glob.glob(glob.escape(prefix) + ".*"):
        os.remove(stale)
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    files = [f for f in glob.glob(glob.escape(prefix) + ".*") if re.fullmatch(r"\d+", f.rsplit(".", 1)[1])]
    files.sort(key=lambda f: int(f.rsplit(".", 1)[1]))
    text = ""
    for f in files:
        with open(f) as handle:
            text += handle.read()
    return done.returncode, done.stdout, text
