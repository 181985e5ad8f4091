#!/usr/bin/python3
"""Runs boltnet on many random networks and compares each with the reference: the table of
docs/verification-2d.md.

Usage: survey.py BOLTNET OUTDIR [--seeds 1-12] [--ranks N] [-option value ...]
For every seed, the 3D scene and the planar one (make_scene.py), boltnet on N ranks (mpiexec),
check_network.py; prints one markdown row per scene: steps (cut-backs), states, the largest
differences in jumps, forces and slips (of each quantity's scale), boltnet's equilibrium residual,
rows on a threshold, slip turns over 10 degrees and the largest, and whether the check passed.
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PY = sys.executable


def main(argv):
    boltnet, out, rest = argv[0], argv[1], argv[2:]
    seeds, ranks, opts = "1-12", 1, []
    it = iter(rest)
    for a in it:
        if a == "--seeds":
            seeds = next(it)
        elif a == "--ranks":
            ranks = int(next(it))
        else:
            opts.append(a)
    lo, hi = map(int, seeds.split("-"))
    print("| scene | steps (cut-backs) | states | du | f | slip | equilibrium | on threshold | turns > 10 deg (largest) | check |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for seed in range(lo, hi + 1):
        for planar in ([], ["--planar"]):
            scene = subprocess.run([PY, os.path.join(HERE, "make_scene.py"), str(seed), out, *planar],
                                   capture_output=True, text=True, check=True).stdout.strip()
            name = os.path.basename(scene)[:-5]
            res = os.path.join(out, name)
            run = subprocess.run(["mpiexec", "-n", str(ranks), "--oversubscribe", boltnet, "-scene", scene, "-output_dir", res, *opts],
                                 capture_output=True, text=True)
            if run.returncode:
                print(f"| {name} | boltnet failed: {run.stdout.strip().splitlines()[-1:]} |")
                continue
            chk = subprocess.run([PY, os.path.join(HERE, "check_network.py"), os.path.join(res, "joints.csv"), scene, *planar, *opts],
                                 capture_output=True, text=True)
            o = chk.stdout
            steps = re.search(r"(\d+) steps \((\d+) from cut-backs\), \d+ joints, states (.*)", o)
            diff = dict(re.findall(r"largest difference in (\w+): (\S+) of", o))
            eq = re.search(r"equilibrium residual: (\S+) of", o).group(1)
            thr = re.search(r"rows on a threshold: (\d+), of which (\d+)", o)
            turn = re.search(r"(\d+) turns over 10 degrees, largest (\S+) degrees", o)
            print(f"| {name} | {steps.group(1)} ({steps.group(2)}) | {steps.group(3)} | {diff['du']} | {diff['f']} | {diff['slip']} | {eq} "
                  f"| {thr.group(1)} ({thr.group(2)} differ) | {turn.group(1)} ({turn.group(2)}) | {'pass' if chk.returncode == 0 else 'FAIL'} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
