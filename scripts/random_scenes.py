"""Unseen scenes for the engine-TAA studies (scripts/engine-taa-motion-study.sh,
scripts/jitter-scale-study.sh): scene files of 3 to 10 random polygons and
circles in random greys, each with a random pan of up to 1.5 pixels per frame
per axis. The same seed gives the same scenes and pans."""
import json
import os
import random


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
