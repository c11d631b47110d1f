#!/usr/bin/env bash
# How much does the pan velocity alone decide which jitter wins? The linear
# model of a pan (aapat sequence pan under TAA at RATIO, by default FSR 2 at
# 1.5; uniform:step=4 acuity) at COUNT random velocities (--random-velocities:
# each component uniform up to 1.5 pixels per frame, as the unseen scenes'
# pans; --seed SEED), each sequence's steady mean E2 against the first's: at
# how many velocities it is lower, the mean change, and the lowest and
# highest, as the command's against_first reports them; a Markdown table on
# stdout. Usage: SEED=7 COUNT=24 scripts/pan-velocity-spread.sh halton \
#   aapat-upscale-1.5 r2 sobol:seed=1 (docs/temporal.md, "Under motion";
# about 3 minutes on 2 cores); TAA=ue4 RATIO=1 for Unreal Engine 4's.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=${AAPAT:-$root/build/release/aapat}
taa=${TAA:-fsr2} ratio=${RATIO:-1.5} count=${COUNT:-24} seed=${SEED:-7}
doc=$("$aapat" sequence pan "$@" --taa "$taa" --ratio "$ratio" --acuity uniform:step=4 \
  --random-velocities "$count" --seed "$seed" --json)
DOC="$doc" /usr/bin/python3 - "$taa" "$ratio" "$count" "$seed" "$1" <<'PY'
import json, os, sys
taa, ratio, count, seed, first = sys.argv[1:6]
print(f"| against {first} ({taa} at {ratio}, {count} velocities, seed {seed}) "
      "| lower at | mean | lowest | highest |")
print("| --- | ---: | ---: | ---: | ---: |")
for row in json.loads(os.environ["DOC"])["rows"][1:]:
    c = row["against_first"]
    print(f"| {row['sequence']} | {c['lower_at']} of {c['velocities']} | "
          f"{100 * c['mean_change']:+.2f} % | {100 * c['lowest_change']:+.1f} % | "
          f"{100 * c['highest_change']:+.1f} % |")
PY
