#!/usr/bin/env bash
# Builds data/sequences/: TAA jitter sequences of 8 and 16 phases that beat
# Halton(2,3) of the same length on worst steady-state E2 and on mean
# flicker under EMA alpha 0.1 (the study's objective: uniform acuity at 1
# degree, L2 over angles). lambda: the weight of the flicker term that beats
# Halton on both with the most even margins among those tried (docs/temporal.md).
# Not part of the test suite: about a minute on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=${AAPAT:-$root/build/release/aapat}
out=$root/data/sequences
mkdir -p "$out"
"$aapat" optimize --sequence 8 --starts 200 --seed 1 --flicker-weight 5 --name aapat-taa-8 -o "$out/aapat-taa-8.json"
"$aapat" optimize --sequence 16 --starts 128 --seed 1 --flicker-weight 5.25 --name aapat-taa-16 -o "$out/aapat-taa-16.json"
# For UE4-style TAA (a min/max clamp, alpha 0.04): aapat-taa-8's objective with
# every jitter within 0.31 of the centre, which wins on moving content under
# UE4's clamp where the unbounded ring does not (docs/temporal.md, "Under
# motion"); the search names it aapat-taa-8, the catalog aapat-ue4-8.
"$aapat" optimize --sequence 8 --starts 200 --seed 1 --flicker-weight 5 --jitter-radius 0.31 \
  --name aapat-ue4-8 -o "$out/aapat-ue4-8.json"
/usr/bin/python3 - "$out/aapat-ue4-8.json" <<'PY'
import json, sys
with open(sys.argv[1]) as f:
    text = f.read()
assert json.loads(text)["name"] == "aapat-taa-8"
with open(sys.argv[1], "w") as f:
    f.write(text.replace('"name": "aapat-taa-8"', '"name": "aapat-ue4-8"', 1))
PY
# Upscaling jitters (docs/temporal.md, "The linear model of upscaling"): the
# upscaler's phase count int(8 R^2) per ratio, optimized under the linear
# model of upscaling through FSR 2's Lanczos-2 reconstruction, accumulating
# as FSR 2 does on still content (EMA alpha 1/17: n <= 16 frames); about
# two minutes on 2 cores.
for spec in 1.5:18:4 1.7:23:4 2:32:4 3:72:2; do
  IFS=: read -r ratio frames starts <<<"$spec"
  "$aapat" optimize --sequence "$frames" --ratio "$ratio" --alpha 0.0588235294117647 \
    --starts "$starts" --seed 1 --name aapat-upscale-$ratio -o "$out/aapat-upscale-$ratio.json"
done
