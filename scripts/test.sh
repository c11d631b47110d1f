#!/usr/bin/env bash
# Installs what is needed, builds the optimized and the ASan+UBSan builds, runs
# every test in both (the Python suite in the optimized one), checks that the
# committed docs/ tables and figures regenerate byte for byte, that the
# installed package builds and runs the example in examples/ and that the
# study's report page and the explorer page (built to WebAssembly) work in
# headless Chromium, then fuzzes each
# parser for a fixed budget under ASan + UBSan (scripts/fuzz.sh;
# AAPAT_FUZZ_SECONDS per target, default 10). This is what CI runs (.ci/run).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
status=0
# Each stage's heading says when it started (minutes:seconds into the run).
at() { printf '[%d:%02d]' $((SECONDS / 60)) $((SECONDS % 60)); }
for preset in release asan; do
  echo "== $(at) ${preset}: configure and build"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset" -j "$jobs"
  echo "== $(at) ${preset}: tests"
  # Each test's line, the output of any that fails, and ctest's summary.
  ctest --preset "$preset" -j "$jobs" --output-on-failure || status=1
  if [ "$preset" = release ]; then
    echo "== $(at) docs: every committed table and figure regenerates byte for byte"
    scripts/check-docs.sh || status=1
    echo "== $(at) the installed package"
    scripts/test-install.sh || status=1
    echo "== $(at) pip install . into a venv"
    scripts/test-pip.sh || status=1
    echo "== $(at) the study report in headless Chromium"
    scripts/test-report.sh || status=1
    echo "== $(at) the explorer page: WebAssembly build, headless Chromium"
    scripts/test-web.sh || status=1
  fi
done
echo "== $(at) fuzz: every parser under ASan + UBSan"
scripts/fuzz.sh build/asan || status=1
echo "== $(at) done, exit $status"
exit "$status"
