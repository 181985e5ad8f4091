#!/bin/bash
# expect.sh: run a command and check how it ends.
#   expect.sh [--fail] [--match REGEX]... [--reject REGEX]... [--unchanged FILE]... -- command [args...]
# --fail            the command must exit non-zero (default: it must exit 0)
# --status N        the command must exit N (with N > 0, implies --fail)
# --match REGEX     its output (stdout and stderr) must match REGEX (grep -E)
# --reject REGEX    its output must not match REGEX
# --unchanged FILE  FILE must be byte-for-byte the same after the command (nothing written is corrupted)
# --max-lines N     its output must have at most N lines (an error is one line, not a traceback)
# --absent PATH     PATH must not exist after the command (nothing was written)
# --info PREFIX     the command writes PETSc's -info to one file per rank (-info PREFIX[:classes]
#                   gives PREFIX.0, PREFIX.1, ...): they are removed before it runs and read with
#                   its output after. On several ranks -info on stdout is not line-safe: mpirun
#                   forwards each rank's block-buffered output as it comes, and a block of one rank
#                   can cut a line of another in two.
set -u
max_lines=''
absent=()
info=''
want_fail=0
want_status=''
matches=()
rejects=()
keep=()
while [ $# -gt 0 ]; do
  case "$1" in
    --fail) want_fail=1 ;;
    --status) want_status=$2; [ "$2" != 0 ] && want_fail=1; shift ;;
    --match) matches+=("$2"); shift ;;
    --reject) rejects+=("$2"); shift ;;
    --unchanged) keep+=("$2"); shift ;;
    --max-lines) max_lines=$2; shift ;;
    --absent) absent+=("$2"); shift ;;
    --info) info=$2; shift ;;
    --) shift; break ;;
    *) echo "expect.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
sums=()
for f in "${keep[@]+"${keep[@]}"}"; do sums+=("$(cksum < "$f")"); done
[ -n "$info" ] && rm -f "$info".[0-9]*
out=$("$@" 2>&1)
status=$?
r=0
while [ -n "$info" ] && [ -f "$info.$r" ]; do
  out+=$'\n'$(cat "$info.$r")
  r=$((r + 1))
done
echo "$out"
echo "[exit status $status]"
ok=1
if [ $want_fail = 1 ] && [ $status = 0 ]; then echo "expect.sh: expected a failure, the command succeeded"; ok=0; fi
if [ $want_fail = 0 ] && [ $status != 0 ]; then echo "expect.sh: expected success, the command exited $status"; ok=0; fi
if [ -n "$want_status" ] && [ "$status" != "$want_status" ]; then echo "expect.sh: expected exit status $want_status, the command exited $status"; ok=0; fi
for r in "${matches[@]+"${matches[@]}"}"; do
  if ! grep -Eq -- "$r" <<<"$out"; then echo "expect.sh: output does not match: $r"; ok=0; fi
done
for r in "${rejects[@]+"${rejects[@]}"}"; do
  if grep -Eq -- "$r" <<<"$out"; then echo "expect.sh: output matches what it must not: $r"; ok=0; fi
done
# A sanitizer's report (scripts/sanitize) is a failure even where the command must fail.
if grep -Eq -- "runtime error: |ERROR: (Address|Leak|UndefinedBehavior)Sanitizer" <<<"$out"; then
  echo "expect.sh: a sanitizer reported an error"; ok=0
fi
if [ -n "$max_lines" ] && [ "$(printf '%s\n' "$out" | wc -l)" -gt "$max_lines" ]; then
  echo "expect.sh: more than $max_lines line(s) of output"; ok=0
fi
for f in "${absent[@]+"${absent[@]}"}"; do
  if [ -e "$f" ]; then echo "expect.sh: $f exists"; ok=0; fi
done
i=0
for f in "${keep[@]+"${keep[@]}"}"; do
  if [ "$(cksum < "$f")" != "${sums[$i]}" ]; then echo "expect.sh: $f was changed"; ok=0; fi
  i=$((i + 1))
done
[ $ok = 1 ] && echo "expect.sh: as expected" && exit 0
exit 1
