#!/usr/bin/env python3
"""Distribution check: summary.json reports the dof imbalance (max over ranks of the
owned dof over their mean) and the cut of parts into patches; assert that the imbalance is at most
LIMIT and that the parts were cut (more patches than parts, joined by seams).

usage: check_balance.py summary.json LIMIT
"""
import json
import sys

summary, limit = sys.argv[1], float(sys.argv[2])
with open(summary) as f:
    s = json.load(f)
print(f"{summary}: {s['parts']} parts in {s['patches']} patches ({s['seams']} seams), "
      f"{s['dof']} dof, dof imbalance {s['dof_imbalance']:.3f} (limit {limit})")
ok = True
if not s["patches"] > s["parts"] or s["seams"] < 1:
    print("FAIL: no part was cut into patches")
    ok = False
if s["dof_imbalance"] > limit:
    print(f"FAIL: dof imbalance {s['dof_imbalance']} > {limit}")
    ok = False
sys.exit(0 if ok else 1)
