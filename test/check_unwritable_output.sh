#!/bin/bash
# An output directory that cannot be written (requirement: bad input gets a clear message and
# corrupts nothing): a run into DIR writes its results, DIR and its files are made read-only, and
# the same run again must exit non-zero with one line naming the directory and -output_dir, leaving
# every file of the first run byte for byte as it was.
#   check_unwritable_output.sh BOLTNET DIR EXPECT -- ARGS...
# Root writes into read-only directories, so as root the second run is made by the unprivileged
# user nobody (setpriv); exits 77 (ctest SKIP_RETURN_CODE) where that user cannot run the program
# or can still write DIR.
set -u
boltnet=$1 dir=$2 expect=$3
shift 4
rm -rf "$dir" && mkdir -p "$dir"
"$boltnet" "$@" -output_dir "$dir" > "$dir.log" 2>&1 || { cat "$dir.log"; echo "check_unwritable_output: the first run failed"; exit 1; }
as=()
if [ "$(id -u)" = 0 ]; then
  command -v setpriv > /dev/null || { echo "check_unwritable_output: no setpriv to drop root: skipped"; exit 77; }
  as=(setpriv --reuid=65534 --regid=65534 --clear-groups env HOME=/tmp)
fi
chmod -R a-w "$dir"
trap 'chmod -R u+w "$dir"' EXIT
if "${as[@]+"${as[@]}"}" sh -c "touch '$dir/probe'" 2> /dev/null; then
  rm -f "$dir/probe"
  echo "check_unwritable_output: $dir stays writable here: skipped"
  exit 77
fi
"${as[@]+"${as[@]}"}" "$boltnet" -help > /dev/null 2>&1 || { echo "check_unwritable_output: the unprivileged user cannot run $boltnet: skipped"; exit 77; }
keep=()
for f in "$dir"/*; do keep+=(--unchanged "$f"); done
"$expect" --fail --max-lines 1 "${keep[@]}" --match "Cannot write results in the output directory '$dir' \(-output_dir\)" -- "${as[@]+"${as[@]}"}" "$boltnet" "$@" -output_dir "$dir"
