#!/usr/bin/python3
"""Checks a single contact-law joint loaded along t1 against the closed form, through the shells.

Requirement (paper sect. 2.1): in fig3a the bolt carries the whole load in x
(the model is statically determinate in x), so its force f_t1 equals the load, and its jump follows
the contact law: du = F/k while |F| <= k j, then sign(F) (j + (|F| - k j)/k'). The forces go through
shell patches and penalty footprints, solved to round-off (docs/solver.md): rtol 1e-7.
With gap 0 the bolt bears at every load, at rest too: du = F/k', state contact (k may be 0).
Usage: check_contact.py joints.csv k kprime gap [rtol]
"""
import csv
import sys

rows = list(csv.DictReader(open(sys.argv[1])))
k, kp, j = map(float, sys.argv[2:5])
rtol = float(sys.argv[5]) if len(sys.argv) > 5 else 1e-7
states = set()
fmax = max(abs(float(r["load"])) for r in rows)
dscale = j if j > 0 else fmax / kp  # the size of "zero" for a jump
for r in rows:
    F = float(r["load"])
    if j == 0:
        du, state = F / kp, "contact"
    else:
        du = F / k if abs(F) <= k * j else (1 if F > 0 else -1) * (j + (abs(F) - k * j) / kp)
        state = "open" if abs(F) <= k * j else "contact"
    got_f, got_du = float(r["f_t1"]), float(r["du_t1"])
    if abs(got_f - F) > rtol * max(abs(F), k * j, fmax if j == 0 else 0) or abs(got_du - du) > rtol * max(abs(du), dscale) or r["state"] != state:
        print(f"step {r['step']} load {F}: expected f {F} du {du} {state}; got f {got_f} du {got_du} {r['state']}")
        sys.exit(1)
    states.add(state)
if states != ({"contact"} if j == 0 else {"open", "contact"}):
    print(f"the path should open and close the clearance; states seen: {sorted(states)}")
    sys.exit(1)
print(f"{len(rows)} rows match the contact law and carry the load")
