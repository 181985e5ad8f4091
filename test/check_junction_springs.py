#!/usr/bin/python3
"""The linear attachment springs of a junction scene against boltnet-identify.

Requirement: the fasteners that attach each box's spars and ribs to its skins are linear springs
whose stiffnesses the generator computes itself (Huth's formula, the bar formula for kn, kr = 1e3 kn
d^2, as docs/identify.md writes them); they must be what boltnet's identification gives for the
same fastener (the junction's frictional fasteners are identified by boltnet itself at start-up).
boltnet-identify prints 8 significant digits: tolerance 1e-7.

usage: check_junction_springs.py BOLTNET_IDENTIFY SCENE.yaml
"""
import json
import re
import subprocess
import sys


def main():
    exe, scene = sys.argv[1], sys.argv[2]
    model = json.load(open(scene[:-5] + ".model.json"))
    springs = {t: p for t, p in model["joint_types"].items() if p["law"] == "spring"}
    if not springs:
        sys.exit(f"{scene}: no spring joint type")
    worst = 0.0
    for t, p in sorted(springs.items()):
        cmd = [exe, "-fastener_d", repr(p["d"]), "-fastener_hole", repr(p["d"]), "-fastener_t1", repr(p["t1"]), "-fastener_t2", repr(p["t2"]),
               "-fastener_E1", repr(p["E1"]), "-fastener_E2", repr(p["E2"]), "-fastener_Ef", repr(model["moduli"]["fastener"]),
               "-fastener_mu", "0.3", "-fastener_preload", "1", "-fastener_formula", "huth", "-fastener_type", p["huth"]]
        out = subprocess.run(cmd, capture_output=True, text=True)
        if out.returncode != 0:
            sys.exit(f"{' '.join(cmd)} failed:\n{out.stdout}{out.stderr}")
        for key in ("kn", "kt", "kr"):
            m = re.search(rf"^\s+{key}: (\S+)$", out.stdout, re.M)
            ref = float(m.group(1))
            err = abs(p[key] - ref) / abs(ref)
            worst = max(worst, err)
            if err > 1e-7:
                print(f"type {t}: {key} = {p[key]:.10g} in the scene, {ref:.10g} from boltnet-identify ({err:.1e})")
                return 1
    print(f"{len(springs)} spring types agree with boltnet-identify (worst {worst:.1e})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
