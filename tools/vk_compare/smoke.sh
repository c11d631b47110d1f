#!/usr/bin/env bash
# The GPU comparison end to end: export a pattern for Vulkan, render a scene
# of triangles with it on whatever Vulkan device there is (Mesa's lavapipe in
# CI), resolve with the exported GLSL, compare with `aapat render`.
# Usage: smoke.sh AAPAT AAPAT_VK_COMPARE WORKDIR. Exit 77: no device that can
# place the samples (ctest reports the test as skipped).
set -euo pipefail
aapat=$1 compare=$2 dir=$3
mkdir -p "$dir"
# The standard 4x positions (every Vulkan device has them) with unequal resolve
# weights, so the comparison checks the tap order and weights of the resolve.
cat > "$dir/weighted-msaa4.json" <<'JSON'
{
  "format": "aapat-pattern",
  "version": 1,
  "name": "weighted-msaa4",
  "description": "standard 4x positions, unequal weights",
  "family": "P(1,1,4)",
  "tile": [1, 1],
  "footprint": "1",
  "sets": [
    [[-0.125, 0.375], [0.375, 0.125], [-0.375, -0.125], [0.125, -0.375]]
  ],
  "kernels": [
    [0.1, 0.2, 0.3, 0.4]
  ],
  "provenance": {}
}
JSON
# Vertices on a 1/256-pixel grid, which rasterizers hold exactly (8 sub-pixel
# bits), so GPU and CPU see the same edges; off the 1/16 sample lattice.
cat > "$dir/triangles.json" <<'JSON'
{"background": 0, "shapes": [
  {"polygon": [[3.30078125, 4.1015625], [58.69921875, 12.19921875], [20.3984375, 57.8984375]], "grey": 1},
  {"polygon": [[30.19921875, 30.6015625], [61.1015625, 35.30078125], [45.80078125, 60.3984375], [33.30078125, 50.51171875]], "grey": 0.25},
  {"polygon": [[5.51171875, 40.19921875], [60.30078125, 44.69921875], [6.1015625, 41.8984375]], "grey": 1}
]}
JSON
"$aapat" export "$dir/weighted-msaa4.json" --api vulkan -o "$dir/weighted-msaa4.vk.txt" >/dev/null
"$compare" "$dir/weighted-msaa4.vk.txt" "$dir/triangles.json" --size 64x64 \
  --gpu "$dir/gpu.png" --cpu "$dir/cpu.png" --expect-max-deviation 1
