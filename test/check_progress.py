#!/usr/bin/python3
"""Checks the driver's progress lines (-load_progress, docs/scenes.md "Progress") against its results.

Requirement: one line per converged step, with the step of the total nominal steps, the load, the
Newton iterations, the counts of sticking, sliding and bearing joints summed over ranks, the elapsed
time and an estimate of the time left; the total counts every segment of the load path, and a
cut-back shows as the part of the nominal step reached and the halvings on the way to it.
References, each written by another path than the progress line:
  - summary.json: the number of converged steps, the Newton iterations and cut-backs of each;
  - joints.csv: the load of each step and the state and bearing of every joint at it (rows gathered
    to rank 0; the progress counts are summed over the ranks' own joints);
  - the nominal step count, given on the command line from the scene's load path (segments x steps).
Usage: check_progress.py stdout.txt summary.json joints.csv nominal-steps
"""
import collections
import csv
import json
import re
import sys

out_path, summary_path, csv_path, nominal = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
LINE = re.compile(r"^step (\d+)/(\d+)(?: at ([0-9.]+) \((\d+) cut-backs?\))?  load (\S+)  newton (\d+)  "
                  r"stick (\d+) slide (\d+) bear (\d+)  elapsed ([0-9.]+) s  left ~([0-9.]+) s$")
errors = []


def fail(msg):
    errors.append(msg)


lines = []
for text in open(out_path):
    if text.startswith("step "):
        m = LINE.match(text.rstrip("\n"))
        if not m:
            fail(f"not a progress line: {text.rstrip()}")
            continue
        g = m.groups()
        lines.append(dict(step=int(g[0]), total=int(g[1]), part=float(g[2]) if g[2] else 1.0, cuts=int(g[3] or 0),
                          load=float(g[4]), newton=int(g[5]), stick=int(g[6]), slide=int(g[7]), bear=int(g[8]),
                          elapsed=float(g[9]), left=float(g[10]), cut_line=g[2] is not None))
summary = json.load(open(summary_path))
rows = collections.defaultdict(list)
for r in csv.DictReader(open(csv_path)):
    rows[int(r["step"])].append(r)

# One line per converged step.
if len(lines) != summary["steps"]:
    fail(f"{len(lines)} progress lines, summary.json has {summary['steps']} converged steps")
if sorted(rows) != list(range(1, summary["steps"] + 1)):
    fail(f"joints.csv has steps {sorted(rows)[:5]}..., not 1..{summary['steps']}")
if summary["status"] != "converged":
    fail(f"the run did not converge: {summary['status']}")

for k, p in enumerate(lines, start=1):
    if k not in rows:
        break
    step_rows = rows[k]
    load = float(step_rows[0]["load"])
    if abs(p["load"] - load) > 1e-5 * max(abs(load), 1e-300):
        fail(f"line {k}: load {p['load']}, joints.csv step {k} has {load}")
    if p["newton"] != summary["newton_iterations"][k - 1]:
        fail(f"line {k}: newton {p['newton']}, summary.json {summary['newton_iterations'][k - 1]}")
    want = (sum(r["state"] == "stick" for r in step_rows), sum(r["state"] == "slide" for r in step_rows),
            sum(int(r["bearing"]) for r in step_rows))
    got = (p["stick"], p["slide"], p["bear"])
    if got != want:
        fail(f"line {k}: stick/slide/bear {got}, joints.csv step {k} has {want}")
    if p["total"] != nominal:
        fail(f"line {k}: total {p['total']} nominal steps, the load path has {nominal}")
    if p["left"] < 0 or (k > 1 and p["elapsed"] < lines[k - 2]["elapsed"]):
        fail(f"line {k}: elapsed {p['elapsed']} s after {lines[k - 2]['elapsed'] if k > 1 else 0} s, left {p['left']} s")

# The nominal steps: each reached once, in order (a line at part 1), the last one last; the parts of
# the lines on the way to one increase; the halvings shown for a nominal step are the cut-backs
# summary.json records for its lines.
reached = [p["step"] for p in lines if p["part"] == 1.0]
if reached != list(range(1, nominal + 1)):
    fail(f"nominal steps reached {reached[:8]}..., not 1..{nominal} in order")
by_step = collections.defaultdict(list)
for k, p in enumerate(lines, start=1):
    by_step[p["step"]].append((k, p))
for s, group in by_step.items():
    parts = [p["part"] for _, p in group]
    if parts != sorted(parts) or len(set(parts)) != len(parts):
        fail(f"nominal step {s}: parts {parts} do not increase")
    cuts = sum(summary["cutbacks_per_step"][k - 1] for k, _ in group)
    if group[-1][1]["cuts"] != cuts:
        fail(f"nominal step {s}: its last line shows {group[-1][1]['cuts']} cut-backs, summary.json {cuts}")
    if (cuts > 0) != all(p["cut_line"] for _, p in group):
        fail(f"nominal step {s}: {cuts} cut-backs but the lines {[k for k, _ in group]} say otherwise")
if lines and lines[-1]["left"] != 0:
    fail(f"the last line leaves {lines[-1]['left']} s")

if errors:
    print("\n".join(errors[:20]))
    sys.exit(1)
last = lines[-1]
print(f"check_progress: {len(lines)} lines = {summary['steps']} converged steps of {nominal} nominal "
      f"({summary['cutbacks']} cut-backs); every step's load, Newton iterations and counts match; last step "
      f"stick {last['stick']} slide {last['slide']} bear {last['bear']} as in joints.csv")
