#!/bin/bash
# A run stopped by SIGTERM leaves none of MUMPS's out-of-core files behind (drivers/ooc_files.hpp).
#   check_ooc_cleanup.sh MODE DIR -- COMMAND...
# Runs COMMAND (the driver, or mpirun of it, with its factors on disk: -mat_mumps_icntl_22 1) in the
# background with MUMPS_OOC_TMPDIR=DIR, waits until MUMPS has written files there (the reference
# that there is something to remove: at most 300 s), sends SIGTERM to it and waits for it to end.
# MODE ours: the driver names the files (boltnet<host>_<pid>_mumps_*), and none may be left.
# MODE user: the user's own MUMPS_OOC_PREFIX, whose files the driver must leave alone: some stay
# (the control, which shows that a stopped run does leave files that nobody removes).
set -u
mode=$1 dir=$2
shift 3
rm -rf "$dir" && mkdir -p "$dir"
export MUMPS_OOC_TMPDIR=$dir
if [ "$mode" = user ]; then export MUMPS_OOC_PREFIX=user; pattern='user_mumps_*'; else unset MUMPS_OOC_PREFIX; pattern='boltnet*_mumps_*'; fi
"$@" > "$dir.log" 2>&1 &
pid=$!
for _ in $(seq 3000); do
  compgen -G "$dir/$pattern" > /dev/null && break
  kill -0 $pid 2> /dev/null || break
  sleep 0.1
done
written=$(compgen -G "$dir/$pattern" | wc -l)
kill -TERM $pid 2> /dev/null
for _ in $(seq 600); do kill -0 $pid 2> /dev/null || break; sleep 0.1; done
if kill -0 $pid 2> /dev/null; then
  pkill -KILL -P $pid; kill -KILL $pid
  echo "check_ooc_cleanup: FAIL: the run did not end within 60 s of SIGTERM"
  exit 1
fi
wait $pid
status=$?
left=$(compgen -G "$dir/$pattern" | wc -l)
echo "check_ooc_cleanup: $mode: $written file(s) '$pattern' when stopped, exit $status, $left left"
[ "$written" -gt 0 ] || { cat "$dir.log"; echo "check_ooc_cleanup: FAIL: MUMPS wrote no out-of-core file before the run ended"; exit 1; }
[ "$status" -ne 0 ] || { echo "check_ooc_cleanup: FAIL: the run ended before SIGTERM stopped it"; exit 1; }
if [ "$mode" = user ]; then
  [ "$left" -gt 0 ] || { echo "check_ooc_cleanup: FAIL: the user's own files were removed"; exit 1; }
  rm -f "$dir"/user_mumps_*
else
  [ "$left" -eq 0 ] || { ls "$dir"; echo "check_ooc_cleanup: FAIL: $left out-of-core file(s) left"; exit 1; }
fi
