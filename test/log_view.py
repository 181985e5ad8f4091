"""The event tables of a PETSc -log_view file (ascii, the default format), for the test scripts.

Each stage has its own table ("--- Event Stage k: name"); an event row starts with the event's
name, its largest count over the ranks ("Count Max"), the count ratio and its largest time over the
ranks ("Time Max"). An event that never ran in a stage may be left out of that stage's table.
"""
import re

_ROW = re.compile(r"^(\w+)\s+(\d+)\s+[\d.]+\s+([\d.]+e[+-]\d+)\s")


def rows(path):
    """[(event, count, time)], one per event row of every stage's table, in file order."""
    out = []
    with open(path) as f:
        for line in f:
            m = _ROW.match(line)
            if m:
                out.append((m.group(1), int(m.group(2)), float(m.group(3))))
    return out


def summed(path):
    """{event: [count, time]} summed over the stages."""
    out = {}
    for name, count, time in rows(path):
        e = out.setdefault(name, [0, 0.0])
        e[0] += count
        e[1] += time
    return out


def largest_counts(path, prefix=""):
    """{event: the largest count of any stage}, for the events whose name starts with prefix."""
    out = {}
    for name, count, _ in rows(path):
        if name.startswith(prefix):
            out[name] = max(out.get(name, 0), count)
    return out
