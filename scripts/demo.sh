#!/usr/bin/env bash
# Installs what is needed, builds aapat, and runs the demo: evaluates the
# catalog's classic patterns under the papers' objective (the numbers of
# Laine-Aila Table 2 and Hasselgren Table 2), optimizes the FLIPQUAD and
# FLIPTRI families from random starts, compares the aapat catalog with the
# standard MSAA patterns under the recommended objective (the default), and
# writes drawings, the per-angle error profile, pattern files and the
# optimizer's starts into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release -j "$(nproc 2>/dev/null || echo 2)" --target aapat >/dev/null
aapat=build/release/aapat
mkdir -p out
echo "== E2 of the classic patterns under the papers' objective (Laine-Aila Eq. 5)"
"$aapat" eval --objective laine-aila centroid diagonal box2x2 rgss quincunx quincunx-hasselgren flipquad fliptri \
  hasselgren-a hasselgren-b hasselgren-c hasselgren-d hasselgren-e hasselgren-f \
  msaa-2 msaa-4 msaa-8 msaa-16 --profile out/profile.svg
"$aapat" eval --objective laine-aila quincunx flipquad fliptri hasselgren-f rgss \
  --profile out/profile.csv >/dev/null
for p in flipquad fliptri quincunx hasselgren-c; do
  "$aapat" show "$p" -o "out/$p.svg" >/dev/null
  "$aapat" show "$p" -o "out/$p.json" >/dev/null
done
echo "== optimize: P(4,1+,2) with FLIPQUAD's sites and P(4,1+,1.25) with FLIPTRI's, 64 random starts"
"$aapat" optimize --objective laine-aila --family 'P(4,1+,2)' --placement left,right,bottom,top \
  --starts 64 --seed 1 \
  -o out/best-flipquad-sites.json --svg out/best-flipquad-sites.svg --csv out/starts-flipquad-sites.csv
"$aapat" optimize --objective laine-aila --family 'P(4,1+,1.25)' --placement top-left,bottom,right \
  --starts 64 --seed 1 \
  -o out/best-fliptri-sites.json --svg out/best-fliptri-sites.svg
echo "== the published patterns beside the optimized ones"
"$aapat" eval --objective laine-aila flipquad hasselgren-f out/best-flipquad-sites.json fliptri \
  hasselgren-a out/best-fliptri-sites.json
echo "== the aapat catalog against the standard MSAA patterns, under the recommended objective"
"$aapat" eval msaa-4 aapat-4 msaa-8 aapat-8 msaa-16 aapat-16
echo "wrote out/: profile.svg, profile.csv, drawings (.svg) and pattern files (.json) of flipquad,"
echo "fliptri, quincunx, hasselgren-c and the two optimized patterns, starts-flipquad-sites.csv"
