#!/usr/bin/python3
"""A scene whose joint type is identified from its geometry at start-up.

Checks that summary.json records the identified parameters, that they equal what boltnet-identify
prints for the same geometry (the same fastener given through the driver's -fastener_* options), and
that the run follows the closed form of the frictional law with those parameters (check_fig3c.py).
Usage: check_identified_scene.py summary.json joints.csv identify-output.txt check_fig3c.py
       check_identified_scene.py summary.json joints.csv identify-output.txt check_hard.py force1d [check_hard options]
"""
import json
import re
import subprocess
import sys

summary = json.load(open(sys.argv[1]))
bolt = summary["identified_joint_types"]["bolt"]
printed = dict(re.findall(r"^\s+(\w+): ([-0-9.eE+]+)\s*$", open(sys.argv[3]).read(), re.M))
for key in ["kn", "kt", "kc", "kg", "gap", "mu", "nf", "pretension"]:
    a, b = float(bolt[key]), float(printed[key])
    if abs(a - b) > 1e-7 * max(abs(a), abs(b), 1e-300):
        print(f"{key}: scene {a}, boltnet-identify {b}")
        sys.exit(1)
print(f"identified: formula {bolt['formula']}, kc {bolt['kc']:.6g} N/mm, gap {bolt['gap']:.6g} mm, G {bolt['G']:.6g} N")
law = [str(bolt["kt"]), str(bolt["kg"]), str(bolt["kc"]), str(bolt["gap"]), str(bolt["G"])]
if len(sys.argv) > 5:  # check_hard.py MODE joints.csv law... options...
    sys.exit(subprocess.call([sys.executable, sys.argv[4], sys.argv[5], sys.argv[2], *law, *sys.argv[6:]]))
sys.exit(subprocess.call([sys.executable, sys.argv[4], sys.argv[2], *law]))
