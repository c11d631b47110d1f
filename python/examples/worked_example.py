"""A worked example of the aapat Python module (docs/python.md).

Evaluates the classic patterns, optimizes a 4-sample pattern, scores 10,000
random patterns in one call, measures a point set, and renders a scene with
the optimized pattern; with matplotlib installed it also draws them into
OUT/worked_example.png. Run:  python3 worked_example.py [OUT]
"""
import sys

import numpy as np

import aapat

out = sys.argv[1] if len(sys.argv) > 1 else "."

# 1. The published patterns under the Laine-Aila metric (Table 2 of both papers).
names = ["box2x2", "rgss", "quincunx", "flipquad", "hasselgren-f"]
for name, e2 in zip(names, aapat.eval(names, objective="laine-aila")):
    print(f"{name:14} {aapat.pattern(name).family:11} E2 {e2:.4f}")

# 2. Optimize P(1,1,4) from 16 random starts: Laine-Aila's best E2 is 0.359.
best = aapat.optimize(family="P(1,1,4)", starts=16, seed=1, objective="laine-aila",
                      border_samples=True)  # the papers' closed pixel
print(f"optimized: {best.description}, E2 {best.e2:.4f}")
print(np.round(best.pattern.sets[0], 4))

# 3. 10,000 random 4-sample patterns in one vectorized call.
rng = np.random.default_rng(0)
random_patterns = rng.random((10000, 4, 2)) - 0.5
e2 = aapat.eval(random_patterns)
print(f"random 4-sample patterns: median E2 {np.median(e2):.3f}, best {e2.min():.3f}")

# 4. A point set: its discrepancies and its radially averaged spectrum.
points = aapat.generate("best-candidate", 1024, seed=1)
d = aapat.discrepancy(points)
print(f"best candidate, 1024 points: L2-star {d['l2_star']:.5f}, edge {d['edge']:.4f}")
spectrum = aapat.spectrum(points, size=128)

# 5. The optimized pattern on the zone plate, against the dense reference.
image = aapat.render("zoneplate", pattern=best.pattern, size=(128, 128), reference=True,
                     reference_samples=256)
print(f"zone plate with the optimized pattern: RMSE {image['rmse']:.3f} (0-255 levels)")

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("(matplotlib is not installed: no figure)")
    sys.exit(0)

fig, ax = plt.subplots(1, 4, figsize=(16, 4))
ax[0].scatter(*best.pattern.sets[0].T, s=400 * best.pattern.weights[0])
ax[0].set(xlim=(-0.5, 0.5), ylim=(-0.5, 0.5), aspect="equal", title=f"P(1,1,4), E2 {best.e2:.3f}")
ax[1].hist(e2, bins=60)
ax[1].set(title="E2 of 10,000 random patterns", xlabel="E2")
ax[2].plot(spectrum["radius"][1:], spectrum["radial_power"][1:])
ax[2].set(title="best candidate: radial power", xlabel="|f|")
ax[3].imshow(image["image"], cmap="gray", vmin=0, vmax=1)
ax[3].set(title="zone plate", xticks=[], yticks=[])
fig.savefig(f"{out}/worked_example.png", dpi=80, bbox_inches="tight")
print(f"wrote {out}/worked_example.png")
