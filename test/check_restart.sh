#!/bin/bash
# check_restart.sh: a run killed with SIGKILL after a checkpoint and restarted from it ends with the
# results of the run that was not interrupted (docs/scenes.md, "Checkpoint and restart").
#   check_restart.sh MPIEXEC BOLTNET RANKS RESTART_RANKS EVERY REFERENCE_DIR OUT_DIR RTOL [--fields JOINTS_CSV FIELDS_RTOL] [--short FILE] -- ARGS...
# 1. boltnet ARGS -checkpoint_every EVERY on RANKS ranks, in a session of its own; as soon as the first
#    checkpoint (step EVERY) is on disk every process of the session is killed with SIGKILL. The test
#    fails if the run had finished by then: it would not have tested a kill.
# 2. A checkpoint.h5.tmp of garbage is left beside the checkpoint (a kill during a checkpoint's
#    write); with --short, FILE of the output directory (fields.h5, joints.h5) is left shorter than
#    its superblock records (damage_fields.py --short), as a kill while HDF5 extended it can leave it, so that
#    the restart must extend it. The run is restarted on RESTART_RANKS ranks with -restart.
# 3. joints.csv and/or joints.h5, whichever REFERENCE_DIR has, against REFERENCE_DIR's (compare_csv.py,
#    check_joint_table.py: RTOL of each quantity's scale), summary.json's
#    record of the steps and, with --fields, fields.h5 + fields.xdmf (check_fields.py --ref, FIELDS_RTOL).
set -u
mpiexec=$1 boltnet=$2 ranks=$3 restart_ranks=$4 every=$5 ref=$6 out=$7 rtol=$8
shift 8
fields=''
if [ "$1" = --fields ]; then fields=$2 fields_rtol=$3; shift 3; fi
short=''
if [ "$1" = --short ]; then short=$2; shift 2; fi
[ "$1" = -- ] && shift
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
py=/usr/bin/python3
die() { echo "check_restart: FAIL: $*"; exit 1; }

rm -rf "$out"
mkdir -p "$out"
ckpt=$out/checkpoint.h5
# setsid: the job leads a session of its own, so that the kill reaches every process of it, MPI
# ranks included, and nothing else. Open MPI's shared-memory segments and session directory go to a
# directory of the test's (a killed job cannot remove them), removed after the kill.
scratch=$out.mpi
rm -rf "$scratch" && mkdir -p "$scratch"
OMPI_MCA_btl_vader_backing_directory=$scratch OMPI_MCA_orte_tmpdir_base=$scratch setsid "$mpiexec" -n "$ranks" --oversubscribe "$boltnet" "$@" -output_dir "$out" -checkpoint_every "$every" > "$out.killed.log" 2>&1 &
job=$!
trap 'kill -9 -- "-$job" 2> /dev/null' EXIT
for _ in $(seq 1 12000); do
  [ -e "$ckpt" ] && break
  kill -0 "$job" 2> /dev/null || break
  sleep 0.01
done
[ -e "$ckpt" ] || { cat "$out.killed.log"; die "no checkpoint was written"; }
kill -9 -- "-$job" 2> /dev/null
for pid in $(ps -eo pid=,sid= | awk -v s="$job" '$2 == s { print $1 }'); do kill -9 "$pid" 2> /dev/null; done
wait "$job" 2> /dev/null
status=$?
rm -rf "$scratch"
[ -e "$out/summary.json" ] && die "the run finished before it was killed (exit $status): give it a longer load path"
[ "$status" -ge 128 ] || die "the killed run exited $status, not by a signal"
kept=$("$py" -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r').attrs['steps'])" "$ckpt")
if [ -e "$out/joints.csv" ]; then
  echo "check_restart: killed (exit $status) with $(($(wc -l < "$out/joints.csv") - 1)) rows in joints.csv; the checkpoint is at step $kept"
else
  echo "check_restart: killed (exit $status) with $("$py" -c "import h5py, sys; print(len(h5py.File(sys.argv[1], 'r')['step']))" "$out/joints.h5" 2> /dev/null || echo "(unreadable)") steps in joints.h5; the checkpoint is at step $kept"
fi

head -c 1000 /dev/urandom > "$ckpt.tmp"
if [ -n "$short" ]; then "$py" "$here/damage_fields.py" --short "$out/$short" || die "could not shorten $out/$short"; fi
"$mpiexec" -n "$restart_ranks" --oversubscribe "$boltnet" "$@" -output_dir "$out" -restart "$ckpt" > "$out.restart.log" 2>&1
status=$?
cat "$out.restart.log"
[ $status = 0 ] || die "the restart exited $status"
grep -q "restart from $ckpt at step $kept" "$out.restart.log" || die "the restart did not start at step $kept"

compared=0
if [ -e "$ref/joints.csv" ]; then
  "$py" "$here/compare_csv.py" "$ref/joints.csv" "$out/joints.csv" "$rtol" || die "joints.csv differs from $ref/joints.csv"
  compared=1
fi
if [ -e "$ref/joints.h5" ]; then
  "$py" "$here/check_joint_table.py" "$out" --ref "$ref" --rtol "$rtol" || die "joints.h5 differs from $ref/joints.h5"
  compared=1
fi
[ $compared = 1 ] || die "$ref has neither joints.csv nor joints.h5"
"$py" - "$ref/summary.json" "$out/summary.json" "$rtol" << 'EOF' || die "summary.json differs"
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
rtol = float(sys.argv[3])
keys = ["status", "steps", "final_load", "cutbacks", "newton_iterations", "cutbacks_per_step", "released", "frozen_share"]
bad = [k for k in keys if a[k] != b[k]]
# The most loaded joint's force to rtol: its step may be another one of equal force (fig3a carries
# 3000 N at steps 30 and 60, equal to round-off).
ma, mb = a["most_loaded_joint"], b["most_loaded_joint"]
if (ma is None) != (mb is None) or (ma and (ma["joint"] != mb["joint"] or abs(ma["in_plane_force"] - mb["in_plane_force"]) > rtol * abs(ma["in_plane_force"]))):
    bad.append("most_loaded_joint")
for k in bad:
    print(f"summary.json {k}: {a[k]} (uninterrupted) vs {b[k]} (restarted)")
print("check_restart: summary.json records the same steps" if not bad else "")
sys.exit(1 if bad else 0)
EOF
if [ -n "$fields" ]; then
  "$py" "$here/check_fields.py" "$out" "$fields" --ref "$ref" --rtol "$fields_rtol" || die "the fields differ from $ref's"
fi
echo "check_restart: PASS"
