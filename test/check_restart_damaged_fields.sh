#!/bin/bash
# check_restart_damaged_fields.sh: a restart goes on where the killed run left a step after the
# checkpoint that HDF5 can neither read nor remove, and ends with the uninterrupted run's results
# (docs/scenes.md, "Checkpoint and restart").
#   check_restart_damaged_fields.sh MPIEXEC BOLTNET RANKS EVERY REFERENCE_DIR OUT_DIR JOINTS_CSV -- ARGS...
# 1. boltnet ARGS -checkpoint_every EVERY on RANKS ranks, to the end: its last checkpoint is at step k,
#    and fields.h5 holds the steps after it, as a run killed after writing them would.
# 2. Step k + 1 of fields.h5 damaged (damage_fields.py: its group's object header overwritten).
# 3. The run restarted from the checkpoint in the same directory (with -output_stresses_cache false,
#    which a restart may change); joints.csv (compare_csv.py, 1e-12)
#    and fields.h5 (check_fields.py --ref, 1e-10) against REFERENCE_DIR's.
set -u
mpiexec=$1 boltnet=$2 ranks=$3 every=$4 ref=$5 out=$6 joints=$7
shift 7
[ "$1" = -- ] && shift
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
py=/usr/bin/python3
die() { echo "check_restart_damaged_fields: FAIL: $*"; exit 1; }

rm -rf "$out"
"$mpiexec" -n "$ranks" --oversubscribe "$boltnet" "$@" -output_dir "$out" -checkpoint_every "$every" > "$out.log" 2>&1 || { cat "$out.log"; die "the first run failed"; }
kept=$("$py" -c "import h5py, sys; print(h5py.File(sys.argv[1], 'r').attrs['steps'])" "$out/checkpoint.h5")
"$py" "$here/damage_fields.py" "$out/fields.h5" $((kept + 1)) || die "could not damage step $((kept + 1))"
# -output_stresses_cache only trades memory for time: a restart may change it (and the steps after the
# restart then take the other path to the same element results).
"$mpiexec" -n "$ranks" --oversubscribe "$boltnet" "$@" -output_dir "$out" -restart "$out/checkpoint.h5" -output_stresses_cache false > "$out.restart.log" 2>&1
status=$?
grep "boltnet:" "$out.restart.log" | cut -c1-300
[ $status = 0 ] || die "the restart exited $status"
grep -q "restart from $out/checkpoint.h5 at step $kept" "$out.restart.log" || die "the restart did not start at step $kept"
"$py" "$here/compare_csv.py" "$ref/joints.csv" "$out/joints.csv" 1e-12 || die "joints.csv differs from $ref/joints.csv"
"$py" "$here/check_fields.py" "$out" "$joints" --ref "$ref" --rtol 1e-10 || die "the fields differ from $ref's"
[ -e "$out/fields.h5.tmp" ] && die "fields.h5.tmp was left behind"
echo "check_restart_damaged_fields: PASS"
