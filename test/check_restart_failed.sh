#!/bin/bash
# check_restart_failed.sh: a restart from a checkpoint written between cut-backs (the load path's
# position in the middle of a target, with halvings spent) fails where the uninterrupted run failed,
# after the same steps: the position is restored whole (docs/scenes.md, "Checkpoint and restart").
#   check_restart_failed.sh BOLTNET OUT_DIR -- ARGS...   (ARGS: a run that fails with exit 3)
set -u
boltnet=$1 out=$2
shift 2
[ "$1" = -- ] && shift
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
py=/usr/bin/python3
die() { echo "check_restart_failed: FAIL: $*"; exit 1; }

rm -rf "$out" "$out.ref"
"$boltnet" "$@" -output_dir "$out" -checkpoint_every 1 > "$out.log" 2>&1
status=$?
[ $status = 3 ] || { cat "$out.log"; die "the run exited $status, not 3 (a failed load step)"; }
mkdir -p "$out.ref"
cp "$out/joints.csv" "$out/summary.json" "$out.ref/"
# The test is about a checkpoint between cut-backs: say so, or fail.
"$py" -c "
import h5py, sys
a = h5py.File(sys.argv[1], 'r').attrs
print(f'check_restart_failed: checkpoint at step {a[\"steps\"]}, increment {a[\"path_sub\"]} after {a[\"path_halved\"]} halving(s)')
sys.exit(0 if a['path_halved'] > 0 and a['path_sub'] != 0 else 1)" "$out/checkpoint.h5" || die "the last checkpoint is not between cut-backs"

"$boltnet" "$@" -output_dir "$out" -restart "$out/checkpoint.h5" > "$out.restart.log" 2>&1
status=$?
grep "boltnet:" "$out.restart.log" | cut -c1-200
[ $status = 3 ] || die "the restart exited $status, not 3"
"$py" "$here/compare_csv.py" "$out.ref/joints.csv" "$out/joints.csv" 1e-12 || die "joints.csv differs"
"$py" - "$out.ref/summary.json" "$out/summary.json" << 'PY' || die "summary.json differs"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
bad = [k for k in ("status", "message", "steps", "final_load", "cutbacks", "newton_iterations", "cutbacks_per_step") if a[k] != b[k]]
for k in bad:
    print(f"summary.json {k}: {a[k]} (uninterrupted) vs {b[k]} (restarted)")
sys.exit(1 if bad else 0)
PY
echo "check_restart_failed: PASS"
