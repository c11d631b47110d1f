#!/usr/bin/env bash
# Installs what is needed, builds the optimized and the ASan+UBSan builds, and
# runs every test in both. This is what CI runs (.ci/run).
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
  ctest --preset "$preset" -j "$jobs" --output-on-failure -Q || status=1
  ctest --preset "$preset" -N | tail -1
done
if [ "$status" -eq 0 ]; then
  # One closing summary for both builds (ctest -Q prints only failures).
  total=$(ctest --preset release -N | awk '/Total Tests:/ {print $3}')
  total_asan=$(ctest --preset asan -N | awk '/Total Tests:/ {print $3}')
  echo "100% tests passed, 0 tests failed out of $((total + total_asan))"
fi
exit "$status"
