#!/usr/bin/env bash
# Runs every libFuzzer target of the asan build (clang, ASan + UBSan) for a
# fixed budget each, starting from its committed seed corpus. Fails on any
# finding: the crashing input is copied into fuzz/regressions/TARGET/, where
# the ordinary test suite replays it from then on (commit it with the fix).
# Usage: scripts/fuzz.sh [BUILD_DIR]; AAPAT_FUZZ_SECONDS sets the budget per
# target (default 10). As many targets run at once as there are cores.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/asan}
seconds=${AAPAT_FUZZ_SECONDS:-10}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
# One target's run; its exit status says whether it found anything.
fuzz_one() {
  local name=$1 binary="$build/$1"
  # Mutations go to a scratch copy; the committed corpus stays as it is.
  mkdir -p "$work/$name/corpus" "$work/$name/artifacts"
  cp fuzz/corpus/"$name"/* "$work/$name/corpus/"
  "$binary" "$work/$name/corpus" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/$name/artifacts/" \
    >"$work/$name/log" 2>&1
}
names=()
for source in fuzz/*_fuzz.cpp; do
  name=$(basename "$source" .cpp)
  [ -x "$build/$name" ] || { echo "fuzz: $build/$name is not built (configure with AAPAT_FUZZ=ON)" >&2; exit 1; }
  names+=("$name")
done
# As many targets at once as there are cores (libFuzzer runs on one): the
# same budget per target in a fraction of the wall time.
jobs=$(nproc 2>/dev/null || echo 2)
for ((first = 0; first < ${#names[@]}; first += jobs)); do
  pids=()
  batch=("${names[@]:first:jobs}")
  for name in "${batch[@]}"; do
    echo "== fuzz $name for ${seconds}s"
    fuzz_one "$name" &
    pids+=($!)
  done
  for k in "${!batch[@]}"; do
    name=${batch[$k]}
    if ! wait "${pids[$k]}"; then
      status=1
      tail -n 40 "$work/$name/log"
      mkdir -p fuzz/regressions/"$name"
      cp "$work/$name"/artifacts/* fuzz/regressions/"$name"/ 2>/dev/null || true
      echo "fuzz $name: FINDING, saved under fuzz/regressions/$name/" >&2
    else
      echo -n "$name: "
      grep -E "stat::number_of_executed_units|stat::new_units_added" "$work/$name/log" | tr '\n' ' '
      echo
    fi
  done
done
if ((status == 0)); then echo "fuzz: 0 findings"; fi
exit "$status"
