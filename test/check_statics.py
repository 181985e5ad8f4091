#!/usr/bin/env python3
"""Statics check: a part held only by one joint and loaded by a force F * load factor makes the
joint carry exactly that force. Asserts f_<component> = SCALE * load at every step of joints.csv,
to RTOL of the largest force.

usage: check_statics.py joints.csv JOINT COMPONENT SCALE RTOL   (COMPONENT: f_n, f_t1 or f_t2)
"""
import csv
import sys

path, joint, comp, scale, rtol = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
rows = [r for r in csv.DictReader(open(path)) if r["joint"] == joint]
if not rows:
    sys.exit(f"{path}: no row for joint {joint}")
ref = max(abs(scale * float(r["load"])) for r in rows)
worst = max(abs(float(r[comp]) - scale * float(r["load"])) for r in rows) / ref
print(f"{path}: joint {joint} {comp} against {scale:g} x load over {len(rows)} steps: worst {worst:.2e} (rtol {rtol:g})")
sys.exit(0 if worst <= rtol else 1)
