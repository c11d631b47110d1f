#!/usr/bin/env bash
# Installs what is needed, builds the optimized and the ASan+UBSan builds, runs
# every test in both, then fuzzes each parser for a fixed budget under ASan +
# UBSan (scripts/fuzz.sh; AAPAT_FUZZ_SECONDS per target, default 20). This is
# what CI runs (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
status=0
for preset in release asan; do
  echo "== ${preset}: configure and build"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  echo "== ${preset}: tests"
  # Each test's line, the output of any that fails, and ctest's summary.
  ctest --preset "$preset" -j "$jobs" --output-on-failure || status=1
done
echo "== fuzz: every parser under ASan + UBSan"
scripts/fuzz.sh build/asan || status=1
exit "$status"
