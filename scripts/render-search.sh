#!/usr/bin/env bash
# A jitter sequence searched on rendered error: a compass search whose
# objective is the full engine pipeline itself (aapat animate SCENE --taa
# PRESET --ratio R --json, 64x64, 32 frames after 64 of warm-up, clamping
# included) on COUNT scene files of random polygons and circles
# (scripts/random_scenes.py, seeded by SEED), each panned at its own random
# velocity and (BOTH_WAYS=1, the default) at the opposite one. Against BASE
# (the engine's own sequence), per render a = log(rmse / BASE's rmse) and
# b = log(flicker / BASE's flicker); the objective is their mean
# a + b + LOSS (max(0, a) + max(0, b)): a scene lost costs more than one won
# gains. Each frame in turn tries STEP in x and y both ways and keeps the
# first try that lowers the objective; a sweep that keeps none halves the
# step, down to MIN_STEP; MAX_TRIES (0: none) ends it early; START_ONLY=1
# writes the start to OUT and renders nothing. Deterministic: the renders
# are. OUT is rewritten (whole, then renamed) at each improvement.
# START: a sequence file or generator spec of BASE's length, or `lattice`:
# the display-phase lattice as long as BASE (`display-lattice:ratio=RATIO`,
# docs/temporal.md: the offsets at which display pixel centres fall in a
# render pixel, -1/3, 0, 1/3 at R = 1.5, in a Latin order).
# Usage: SEED=1001 COUNT=40 scripts/render-search.sh fsr2 1.5 lattice \
#   halton:frames=18 OUT.json (docs/temporal.md, "Under motion": "A search on
# the renders themselves"). On 2 cores with the references cached, a try
# renders 2 COUNT scenes (COUNT with BOTH_WAYS=0) at about 0.1 s each.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
aapat=${AAPAT:-$root/build/release/aapat}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
AAPAT="$aapat" WORK="$work" PYTHONPATH="$root/scripts" /usr/bin/python3 - "$@" <<'PY'
import concurrent.futures, json, math, os, subprocess, sys

import random_scenes

aapat, work = os.environ["AAPAT"], os.environ["WORK"]
preset, ratio, start, base_spec, out = sys.argv[1:6]
count, seed = int(os.environ.get("COUNT", 40)), int(os.environ.get("SEED", 1001))
loss = float(os.environ.get("LOSS", 0.5))
step, min_step = float(os.environ.get("STEP", 1 / 16)), float(os.environ.get("MIN_STEP", 1 / 128))
max_tries = int(os.environ.get("MAX_TRIES", 0))
first_step = step
scenes, pans = random_scenes.make(count, seed, work, 64)
if os.environ.get("BOTH_WAYS", "1") == "1":
    # Each scene panned both ways: motion has no preferred direction, and a
    # search on one-way pans learns the set's mean direction (docs/temporal.md).
    scenes, pans = scenes + scenes, pans + [random_scenes.reverse(p) for p in pans]

pool = concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2)
def measure(sequence):
    return list(pool.map(lambda i: random_scenes.rendered(aapat, scenes[i], preset, ratio, sequence,
                                                          pans[i]), range(len(scenes))))

def objective(m):
    total = 0.0
    for (r, f), (rb, fb) in zip(m, base):
        a, b = math.log(r / rb), math.log(f / fb)
        total += a + b + loss * (max(0.0, a) + max(0.0, b))
    return total / len(scenes)
def wins(m):
    return (sum(r < rb for (r, _), (rb, _) in zip(m, base)),
            sum(f < fb for (_, f), (_, fb) in zip(m, base)))

def jitter_of(spec_or_file):
    """A sequence file's jitter, or a generator spec's (aapat sequence generate)."""
    if os.path.isfile(spec_or_file):
        return [tuple(p) for p in json.load(open(spec_or_file))["jitter"]]
    return [tuple(p) for p in json.loads(subprocess.run(
        [aapat, "sequence", "generate", spec_or_file, "-o", "-"], check=True,
        capture_output=True, text=True).stdout)["jitter"]]

frames = len(jitter_of(base_spec))
if start == "lattice":  # the library's display-phase lattice, as long as BASE
    start = f"display-lattice:ratio={ratio},frames={frames}"
jitter = jitter_of(start)
if len(jitter) != frames:
    sys.exit(f"render-search: START has {len(jitter)} frames, BASE {frames}")

def save(path, pts, value=None, m=None, tries=0):
    """Writes a sequence file (whole, then renamed); with a measurement, its
    objective and wins go into the provenance."""
    doc = {"format": "aapat-sequence", "version": 1, "name": os.path.splitext(os.path.basename(out))[0],
           "description": f"{len(pts)} frames of 1 sample(s) searched on rendered rmse and flicker "
                          f"under {preset} at ratio {ratio}, panning",
           "family": "P(1,1,1)", "jitter": [list(p) for p in pts],
           "provenance": {"optimizer": "scripts/render-search.sh (compass search on rendered error)",
                          "taa": preset, "ratio": ratio, "start": start, "base": base_spec,
                          "scenes": str(count), "seed": str(seed),
                          "both_ways": os.environ.get("BOTH_WAYS", "1"), "loss_weight": str(loss),
                          "step": str(first_step), "min_step": str(min_step),
                          "max_tries": str(max_tries)}}
    if m is not None:
        doc["provenance"].update({"tries": str(tries), "objective": f"{value:.6f}",
                                  "rmse_wins": str(wins(m)[0]), "flicker_wins": str(wins(m)[1])})
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    os.replace(tmp, path)

if os.environ.get("START_ONLY") == "1":
    save(out, jitter)
    sys.exit(0)
base = measure(base_spec)
candidate = os.path.join(work, "candidate.json")
save(candidate, jitter)
m = measure(candidate)
best, tries = objective(m), 0
save(out, jitter, best, m, tries)
print(f"start {start}: objective {best:.5f}, lower rmse in {wins(m)[0]} of {len(scenes)}, "
      f"flicker in {wins(m)[1]}", flush=True)
while step >= min_step and not (max_tries and tries >= max_tries):
    kept = 0
    for k in range(len(jitter)):
        for dx, dy in ((step, 0), (-step, 0), (0, step), (0, -step)):
            if max_tries and tries >= max_tries:
                break
            x, y = jitter[k][0] + dx, jitter[k][1] + dy
            if abs(x) > 0.5 or abs(y) > 0.5:
                continue
            trial = list(jitter)
            trial[k] = (x, y)
            save(candidate, trial)
            m = measure(candidate)
            value = objective(m)
            tries += 1
            if value < best:
                best, jitter, kept = value, trial, kept + 1
                save(out, jitter, best, m, tries)
                print(f"  frame {k} step {step:g}: objective {best:.5f}, lower rmse in "
                      f"{wins(m)[0]}, flicker in {wins(m)[1]} ({tries} tries)", flush=True)
                break
    print(f"sweep at step {step:g}: {kept} kept, objective {best:.5f}, {tries} tries", flush=True)
    if kept == 0:
        step /= 2
PY
