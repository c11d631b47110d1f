#!/usr/bin/env bash
# Runs a fuzz target once on every file of the given folders (the committed
# seed corpus and the regression files that past findings left); fails if
# the target fails on any of them. Usage: replay.sh TARGET DIR...
set -euo pipefail
target=$1
shift
files=()
for dir in "$@"; do
  [ -d "$dir" ] || continue
  while IFS= read -r -d '' f; do files+=("$f"); done < <(find "$dir" -type f -print0 | sort -z)
done
if ((${#files[@]} == 0)); then
  echo "no inputs to replay in $*" >&2
  exit 1
fi
exec "$target" "${files[@]}"
