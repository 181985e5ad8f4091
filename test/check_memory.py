#!/usr/bin/python3
"""Checks the resident memory a run reports (summary.json's memory_mb, the driver's last lines).

Requirement: summary.json gives, for each phase of the set-up (the model read, its layout, the
network, the patch operators, the whole set-up) and for the peak, the smallest and the largest
resident set over the ranks, in MB; the driver prints the peak.
Reference: the operating system's own count, read by this script as the parent of the run: the
largest resident set of any process it started (getrusage(RUSAGE_CHILDREN).ru_maxrss: mpiexec
and every rank), which is the largest rank's peak. The run's peak is read before it writes its
last files, so it may be slightly below; it may never be above.
Usage: check_memory.py OUTPUT_DIR COMMAND...   (COMMAND writes OUTPUT_DIR/summary.json)
"""
import json
import re
import resource
import subprocess
import sys

out_dir, cmd = sys.argv[1], sys.argv[2:]
run = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
print(run.stdout)
if run.returncode != 0:
    sys.exit(f"the run failed (exit {run.returncode})")
os_peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024 / 1e6  # KiB on Linux
mem = json.load(open(f"{out_dir}/summary.json"))["memory_mb"]
errors = []
phases = ["model", "layout", "network", "operators", "setup", "peak"]
if list(mem) != phases:
    errors.append(f"memory_mb has {list(mem)}, expected {phases}")
for name, (lo, hi) in mem.items():
    if not 0 < lo <= hi:
        errors.append(f"{name}: [{lo}, {hi}] is not a range of positive sizes")
    if hi > mem["peak"][1] + 1:
        errors.append(f"{name}: {hi} MB on a rank, above the reported peak {mem['peak'][1]} MB")
peak = mem["peak"][1]
print(f"reported peak {peak} MB, the operating system's {os_peak:.1f} MB")
if not 0.9 * os_peak <= peak <= os_peak + 1:
    errors.append(f"the reported peak {peak} MB is not the operating system's {os_peak:.1f} MB (within 10 % below)")
m = re.search(r"peak resident memory per rank (\d+) MB \(largest\), (\d+) MB \(smallest\)", run.stdout)
if not m or [int(m.group(2)), int(m.group(1))] != mem["peak"]:
    errors.append(f"the driver's peak line does not say summary.json's {mem['peak']}")
if errors:
    sys.exit("\n".join(errors))
print("memory report matches the operating system's count")
