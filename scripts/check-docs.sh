#!/usr/bin/env bash
# Regenerates every committed table and figure under docs/ into a scratch
# folder with the release build and compares them byte for byte with the
# committed ones: the check that a restructuring changed no output.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
AAPAT_DOCS_OUT=$out "$root/scripts/docs-figures.sh" >/dev/null
status=0
while IFS= read -r -d '' file; do
  rel=${file#"$out"/}
  if ! cmp -s "$file" "$root/$rel"; then
    echo "differs: $rel"
    status=1
  fi
done < <(find "$out" -type f -print0)
[ "$status" -eq 0 ] && echo "docs: every regenerated table and figure is byte-identical"
exit "$status"
