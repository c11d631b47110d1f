#!/usr/bin/env bash
# The study report in a real browser (Debian's headless Chromium): a small
# study's page loads with no console message, shows every figure (the page's
# own check, read back from the DOM), and its screenshot matches the committed
# one (testdata/study-report-small.png) within a tolerance: at most 2% of the
# pixels may differ by more than 48 grey levels (anti-aliasing and font hinting
# move a few pixels from machine to machine; a missing figure moves thousands).
# AAPAT_UPDATE_SCREENSHOT=1 writes the screenshot instead of comparing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=${1:-$root/build/release/aapat}
browser=$(command -v chromium || true)
[ -n "$browser" ] || { echo "test-report: chromium is not installed (scripts/install-deps.sh)"; exit 1; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$aapat" study --budgets 2 --patterns 12 --starts 2 --frames 4 --size 32 \
  --reference-samples 64 --resamples 100 --no-cache --html "$out/report.html" >/dev/null
flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run
  --disable-background-networking --disable-component-update --disable-sync
  --user-data-dir="$out/profile" --virtual-time-budget=5000 --hide-scrollbars)
"$browser" "${flags[@]}" --enable-logging=stderr --v=0 --dump-dom "file://$out/report.html" \
  >"$out/dom.html" 2>"$out/log.txt"
status=0
if grep -q "CONSOLE" "$out/log.txt"; then
  echo "test-report: the page wrote to the console:"
  grep "CONSOLE" "$out/log.txt"
  status=1
fi
figures=$(grep -o 'data-figures="[0-9]*"' "$out/dom.html" | grep -o '[0-9]*' || echo 0)
shown=$(grep -o 'data-figures-shown="[0-9]*"' "$out/dom.html" | grep -o '[0-9]*' || echo 0)
if [ "$figures" -lt 5 ] || [ "$figures" != "$shown" ]; then
  echo "test-report: $shown of $figures figures shown (expected 5 or more, all)"
  status=1
fi
"$browser" "${flags[@]}" --window-size=1000,1500 --screenshot="$out/shot.png" \
  "file://$out/report.html" >/dev/null 2>&1
reference=$root/testdata/study-report-small.png
if [ "${AAPAT_UPDATE_SCREENSHOT:-0}" = 1 ]; then
  cp "$out/shot.png" "$reference"
  echo "test-report: wrote $reference"
  exit "$status"
fi
/usr/bin/python3 - "$out/shot.png" "$reference" <<'PY' || status=1
import sys
import numpy as np
from PIL import Image
shot = np.asarray(Image.open(sys.argv[1]).convert("L"), dtype=np.int16)
ref = np.asarray(Image.open(sys.argv[2]).convert("L"), dtype=np.int16)
if shot.shape != ref.shape:
    sys.exit(f"test-report: screenshot {shot.shape} against the committed {ref.shape}")
differ = np.mean(np.abs(shot - ref) > 48)
if differ > 0.02:
    sys.exit(f"test-report: {100 * differ:.2f}% of the pixels differ from the committed screenshot")
print(f"test-report: page loads, {sys.argv[1] and 'every figure shown'}, screenshot within tolerance ({100 * differ:.3f}% differ)")
PY
exit "$status"
