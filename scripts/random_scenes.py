"""Unseen scenes for the engine-TAA studies (scripts/engine-taa-motion-study.sh,
scripts/jitter-scale-study.sh, scripts/render-search.sh): scene files of 3 to
10 random polygons and circles in random greys, each with a random pan of up
to 1.5 pixels per frame per axis. The same seed gives the same scenes and
pans. And the one render the studies compare them by."""
import json
import os
import random
import subprocess


def make(count, seed, folder, size=64):
    """Writes count scene files under folder; returns their paths and pans."""
    rng = random.Random(seed)
    scenes, pans = [], []
    for i in range(count):
        shapes = []
        for _ in range(rng.randint(3, 10)):
            if rng.random() < 0.5:
                cx, cy, r = rng.uniform(0, size), rng.uniform(0, size), rng.uniform(8, size / 2)
                shapes.append({"polygon": [[cx + rng.uniform(-r, r), cy + rng.uniform(-r, r)]
                                           for _ in range(rng.randint(3, 6))],
                               "grey": round(rng.random(), 3)})
            else:
                shapes.append({"circle": [rng.uniform(0, size), rng.uniform(0, size)],
                               "radius": rng.uniform(3, size / 4), "grey": round(rng.random(), 3)})
        path = os.path.join(folder, f"scene-{i}.json")
        with open(path, "w") as f:
            json.dump({"format": "aapat-scene", "background": round(rng.random(), 3),
                       "shapes": shapes}, f)
        scenes.append(path)
        pans.append(f"pan:dx={rng.uniform(-1.5, 1.5):.3f},dy={rng.uniform(-1.5, 1.5):.3f}")
    return scenes, pans


def reverse(pan):
    """The opposite pan: pan:dx=-DX,dy=-DY for pan:dx=DX,dy=DY."""
    return "pan:" + ",".join(f"{key}={-float(value):.3f}" for key, value in
                             (item.split("=") for item in pan[len("pan:"):].split(",")))


def rendered(aapat, scene, preset, ratio, sequence, motion, size=64, options=()):
    """The mean rmse and flicker over frames of `aapat animate SCENE --taa
    PRESET ... --json` (the engine pipeline; its default frames and warm-up),
    at `ratio` (a string; "1": none given), with further `options`."""
    args = [aapat, "animate", scene, "--taa", preset, "--sequence", sequence, "--motion", motion,
            "--size", str(size), "--json", *options]
    if ratio != "1":
        args += ["--ratio", ratio]
    d = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    return d["rmse"], d["flicker"]
