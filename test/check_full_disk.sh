#!/bin/bash
# A full disk while results are written (requirement: every write is checked; the run exits
# non-zero naming the file and the reason, and leaves no summary.json claiming success).
#   check_full_disk.sh WHAT OUTDIR MATCH -- command...
# WHAT is the file of OUTDIR made a symbolic link to /dev/full before the run (every write to
# /dev/full fails with ENOSPC at the flush): joints.csv, summary.json.tmp or fields.xdmf.tmp.
# Exits 77 (ctest SKIP_RETURN_CODE) where /dev/full does not behave so: the check needs no root.
set -u
what=$1 dir=$2 match=$3
shift 4
if [ ! -c /dev/full ] || printf x 2>/dev/null > /dev/full; then
  echo "check_full_disk.sh: /dev/full is missing or accepts writes here: skipped"
  exit 77
fi
rm -rf "$dir" && mkdir -p "$dir" && ln -s /dev/full "$dir/$what"
out=$("$@" 2>&1)
status=$?
echo "$out"
echo "[exit status $status]"
ok=1
[ $status != 0 ] || { echo "check_full_disk.sh: the run exited 0 on a full disk"; ok=0; }
grep -Eq -- "$match" <<<"$out" || { echo "check_full_disk.sh: output does not match: $match"; ok=0; }
if [ -e "$dir/summary.json" ] && grep -q '"status": "converged"' "$dir/summary.json"; then
  echo "check_full_disk.sh: $dir/summary.json claims success"; ok=0
fi
if [ -e "$dir/summary.json.tmp" ] || [ -L "$dir/summary.json.tmp" ]; then
  echo "check_full_disk.sh: the temporary summary.json.tmp was left behind"; ok=0
fi
! grep -Eq -- "runtime error: |ERROR: (Address|Leak|UndefinedBehavior)Sanitizer" <<<"$out" || { echo "check_full_disk.sh: a sanitizer reported an error"; ok=0; }
[ "$(grep -c 'PETSC ERROR' <<<"$out")" = 0 ] || { echo "check_full_disk.sh: PETSc's traceback was printed"; ok=0; }
[ $ok = 1 ] && echo "check_full_disk.sh: as expected" && exit 0
exit 1
