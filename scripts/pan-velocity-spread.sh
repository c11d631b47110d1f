#!/usr/bin/env bash
# How much does the pan velocity alone decide which jitter wins? The linear
# model of a pan (aapat sequence pan under TAA at RATIO, by default FSR 2 at
# 1.5; uniform:step=4 acuity) at COUNT random velocities (uniform up to 1.5
# pixels per frame per axis, as the unseen scenes' pans; seeded by SEED),
# each sequence's steady mean E2 against the first's: at how many velocities
# it is lower, the mean change, and the lowest and highest. A Markdown table
# on stdout. Usage: SEED=7 COUNT=24 scripts/pan-velocity-spread.sh halton \
#   aapat-upscale-1.5 r2 sobol:seed=1 (docs/temporal.md, "Under motion";
# about 2 minutes on 2 cores); TAA=ue4 RATIO=1 for Unreal Engine 4's.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=${AAPAT:-$root/build/release/aapat}
AAPAT="$aapat" /usr/bin/python3 - "$@" <<'PY'
import json, os, random, subprocess, sys

aapat, sequences = os.environ["AAPAT"], sys.argv[1:]
taa, ratio = os.environ.get("TAA", "fsr2"), os.environ.get("RATIO", "1.5")
count, seed = int(os.environ.get("COUNT", 24)), int(os.environ.get("SEED", 7))
rng = random.Random(seed)
args = [aapat, "sequence", "pan", *sequences, "--taa", taa, "--ratio", ratio,
        "--acuity", "uniform:step=4", "--json"]
for _ in range(count):
    args += ["--velocity", f"{rng.uniform(-1.5, 1.5):.3f},{rng.uniform(-1.5, 1.5):.3f}"]
doc = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
rows = [[v["mean_e2"] for v in r["velocities"]] for r in doc["rows"]]
print(f"| against {sequences[0]} ({taa} at {ratio}, {count} velocities, seed {seed}) "
      "| lower at | mean | lowest | highest |")
print("| --- | ---: | ---: | ---: | ---: |")
for name, row in zip(sequences[1:], rows[1:]):
    change = [100 * (a / b - 1) for a, b in zip(row, rows[0])]
    print(f"| {name} | {sum(c < 0 for c in change)} of {count} | {sum(change) / count:+.2f} % | "
          f"{min(change):+.1f} % | {max(change):+.1f} % |")
PY
