#!/usr/bin/env bash
# Installs what is needed, builds the optimized and the ASan+UBSan builds, runs
# every test in both (the Python suite in the optimized one), checks that the
# committed docs/ tables and figures regenerate byte for byte, that the
# installed package builds and runs the example in examples/ and that the
# study's report page and the explorer page (built to WebAssembly) work in
# headless Chromium, then fuzzes each
# parser for a fixed budget under ASan + UBSan (scripts/fuzz.sh;
# AAPAT_FUZZ_SECONDS per target, default 10). This is what CI runs (.ci/run).
#
# The ASan build compiles at the lowest CPU priority (SCHED_IDLE, and nice 19
# where that is refused) while the optimized build's checks run: those leave a
# core idle for part of their time (single-threaded commands, links, browser
# start-up), which the ASan build takes; they keep their priority.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
status=0
# Each stage's heading says when it started (minutes:seconds into the run).
at() { printf '[%d:%02d]' $((SECONDS / 60)) $((SECONDS % 60)); }

echo "== $(at) release: configure and build"
cmake --preset release >/dev/null
cmake --build --preset release -j "$jobs"

echo "== $(at) asan: configure and build, in the background at the lowest priority (its log follows the release checks)"
mkdir -p build
asan_log=build/asan-build.log
# Its own process group (job control on for the launch), so that an exit or
# Ctrl-C below stops all of it.
idle=(chrt --idle 0)
"${idle[@]}" true 2>/dev/null || idle=()
set -m
"${idle[@]}" nice -n 19 bash -c 'cmake --preset asan >/dev/null && cmake --build --preset asan -j "$1"' \
  asan-build "$jobs" >"$asan_log" 2>&1 &
asan_build=$!
set +m
trap 'kill -- "-$asan_build" 2>/dev/null || true' EXIT

echo "== $(at) release: tests"
# Each test's line, the output of any that fails, and ctest's summary.
ctest --preset release -j "$jobs" --output-on-failure || status=1
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

echo "== $(at) asan: waiting for the background build"
asan_status=0
wait "$asan_build" || asan_status=$?
trap - EXIT
cat "$asan_log"
if [ "$asan_status" -ne 0 ]; then
  echo "== $(at) asan: the build failed (exit $asan_status)"
  echo "== $(at) done, exit 1"
  exit 1
fi
echo "== $(at) asan: tests"
ctest --preset asan -j "$jobs" --output-on-failure || status=1
echo "== $(at) fuzz: every parser under ASan + UBSan"
scripts/fuzz.sh build/asan || status=1
echo "== $(at) done, exit $status"
exit "$status"
