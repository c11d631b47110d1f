#!/usr/bin/env bash
# Runs every libFuzzer target of the asan build (clang, ASan + UBSan) for a
# fixed budget each, starting from its committed seed corpus. Fails on any
# finding: the crashing input is copied into fuzz/regressions/TARGET/, where
# the ordinary test suite replays it from then on (commit it with the fix).
# Usage: scripts/fuzz.sh [BUILD_DIR]; AAPAT_FUZZ_SECONDS sets the budget per
# target (default 20).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/asan}
seconds=${AAPAT_FUZZ_SECONDS:-10}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
for source in fuzz/*_fuzz.cpp; do
  name=$(basename "$source" .cpp)
  binary="$build/$name"
  [ -x "$binary" ] || { echo "fuzz: $binary is not built (configure with AAPAT_FUZZ=ON)" >&2; exit 1; }
  # Mutations go to a scratch copy; the committed corpus stays as it is.
  mkdir -p "$work/$name/corpus" "$work/$name/artifacts"
  cp fuzz/corpus/"$name"/* "$work/$name/corpus/"
  echo "== fuzz $name for ${seconds}s"
  if ! "$binary" "$work/$name/corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/$name/artifacts/" \
      >"$work/$name/log" 2>&1; then
    status=1
    tail -n 40 "$work/$name/log"
    mkdir -p fuzz/regressions/"$name"
    cp "$work/$name"/artifacts/* fuzz/regressions/"$name"/ 2>/dev/null || true
    echo "fuzz $name: FINDING, saved under fuzz/regressions/$name/" >&2
  else
    grep -E "stat::number_of_executed_units|stat::new_units_added" "$work/$name/log" | tr '\n' ' '
    echo
  fi
done
if ((status == 0)); then echo "fuzz: 0 findings"; fi
exit "$status"
