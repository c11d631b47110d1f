#!/usr/bin/env bash
# Regenerates the figures and tables committed under docs/ from a release build.
set -euo pipefail
cd "$(dirname "$0")/.."
aapat=build/release/aapat
[ -x "$aapat" ] || { cmake --preset release >/dev/null && cmake --build --preset release --target aapat >/dev/null; }
img=docs/images
mkdir -p "$img"
"$aapat" eval centroid diagonal box2x2 rgss quincunx quincunx-hasselgren flipquad fliptri \
  hasselgren-a hasselgren-b hasselgren-c hasselgren-d hasselgren-e hasselgren-f \
  msaa-2 msaa-4 msaa-8 msaa-16 --profile "$img/profile.svg" >/dev/null
"$aapat" show flipquad -o "$img/flipquad.svg" >/dev/null
"$aapat" figure10 --starts 256 --csv docs/figure10.csv --svg "$img/figure10.svg" > docs/figure10.txt
"$aapat" enumerate --optimize --csv docs/enumerate.csv --gallery "$img/enumerate-gallery.svg" > docs/enumerate.txt
# Spectra: 1024 points, 256 x 256 frequencies, 10 realizations (Halton is deterministic).
for g in jittered poisson best-candidate halton; do
  "$aapat" spectrum "$g" --n 1024 --size 256 --realizations 10 -o "$img/spectrum-$g.png" \
    --csv "docs/spectrum-$g.csv" --svg "$img/radial-$g.svg" >/dev/null
done
# Goss & Wu Figure 8: 1D Poisson disk against uniform jitter, 7488 samples, 128K frequencies.
"$aapat" spectrum --1d poisson,jittered --n 7488 --frequencies 131072 --max-frequency 4 \
  --svg "$img/spectrum-1d.svg" >/dev/null
echo "figures written under docs/"
