#!/usr/bin/env bash
# Does a tighter jitter win on moving content under an engine's clamp? A
# sequence (a file or a catalog name) scaled toward the pixel centre by each
# SCALE, against the engine's own sequence, through the full engine pipeline
# (aapat animate SCENE --taa PRESET --json, 64x64, 32 frames after 64 of
# warm-up) on COUNT scene files of random polygons and circles (seeded by
# SEED, as scripts/engine-taa-motion-study.sh makes them), each panned at a
# random velocity and then still. One line per scale: in how many scenes the
# scaled sequence has the lower rmse and flicker, and the mean change.
# Usage: SEED=77 COUNT=10 scripts/jitter-scale-study.sh ue4 1 aapat-taa-8 \
#   ue4-halton:frames=8 1 0.95 0.9 (docs/temporal.md, "Under motion"). About
# 4 minutes per 10 scenes and scale on 2 cores. TAA_SET="KEY=VALUE ..." passes
# each item as --taa-set (rectify=none: the linear pipeline, as the pan model);
# REVERSE=1 pans each scene the other way. Under each scale's line, the change
# per scene (rmse / flicker, %), moving then still.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=${AAPAT:-$root/build/release/aapat}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ROOT="$root" AAPAT="$aapat" WORK="$work" PYTHONPATH="$root/scripts" /usr/bin/python3 - "$@" <<'PY'
import concurrent.futures, json, os, sys

import random_scenes

aapat, work = os.environ["AAPAT"], os.environ["WORK"]
preset, ratio, ours, theirs = sys.argv[1:5]
scales = [float(s) for s in sys.argv[5:]]
count, seed, size = int(os.environ.get("COUNT", 10)), int(os.environ.get("SEED", 77)), 64
scenes, pans = random_scenes.make(count, seed, work, size)
if os.environ.get("REVERSE") == "1":
    pans = [random_scenes.reverse(p) for p in pans]

# The sequence's file: a catalog name is data/sequences/NAME.json.
catalog = os.path.join(os.environ["ROOT"], "data", "sequences", ours + ".json")
base = json.load(open(ours if os.path.exists(ours) else catalog))
scaled = {}
for s in scales:
    path = os.path.join(work, f"scaled-{s}.json")
    with open(path, "w") as f:
        json.dump({"format": "aapat-sequence", "version": 1, "name": f"{base['name']} x{s}",
                   "family": "P(1,1,1)", "jitter": [[x * s, y * s] for x, y in base["jitter"]]}, f)
    scaled[s] = path

taa_set = []
for item in os.environ.get("TAA_SET", "").split():
    taa_set += ["--taa-set", item]
def run(scene, sequence, motion):
    return random_scenes.rendered(aapat, scene, preset, ratio, sequence, motion, size, taa_set)

jobs = {}
with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
    for i in range(count):
        for still in (False, True):
            motion = "static" if still else pans[i]
            jobs[(i, still, None)] = pool.submit(run, scenes[i], theirs, motion)
            for s in scales:
                jobs[(i, still, s)] = pool.submit(run, scenes[i], scaled[s], motion)
settings = f" (--taa-set {os.environ['TAA_SET']})" if os.environ.get("TAA_SET") else ""
settings += ", pans reversed" if os.environ.get("REVERSE") == "1" else ""
print(f"{preset} at ratio {ratio}{settings}, seed {seed}: {ours} scaled against {theirs}, "
      f"{count} scenes")
for s in scales:
    cells, per_scene = [], []
    for still in (False, True):
        rmse = flicker = 0
        d_rmse = d_flicker = 0.0
        for i in range(count):
            a, b = jobs[(i, still, s)].result(), jobs[(i, still, None)].result()
            rmse += a[0] < b[0]
            flicker += a[1] < b[1]
            d_rmse += (a[0] / b[0] - 1) / count
            d_flicker += (a[1] / b[1] - 1) / count
            per_scene.append(f"{100 * (a[0] / b[0] - 1):+.1f}/{100 * (a[1] / b[1] - 1):+.1f}")
        cells.append(f"{'still' if still else 'moving'}: rmse {rmse}/{count} "
                     f"({100 * d_rmse:+.2f} %), flicker {flicker}/{count} ({100 * d_flicker:+.2f} %)")
    print(f"x{s}: " + "; ".join(cells))
    print(f"  moving {' '.join(per_scene[:count])}; still {' '.join(per_scene[count:])}")
PY
