#!/usr/bin/env bash
# Regenerates the figures and tables committed under docs/ from a release build.
# AAPAT_DOCS_OUT writes them under another folder instead (scripts/check-docs.sh
# compares the two).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
aapat=$root/build/release/aapat
[ -x "$aapat" ] || { cmake --preset release >/dev/null && cmake --build --preset release --target aapat >/dev/null; }
cd "${AAPAT_DOCS_OUT:-$root}"
mkdir -p docs
img=docs/images
mkdir -p "$img"
# The papers' reproductions name the papers' objective (laine-aila); everything else
# evaluates under the default, the recommended objective.
"$aapat" eval --objective laine-aila centroid diagonal box2x2 rgss quincunx quincunx-hasselgren flipquad fliptri \
  hasselgren-a hasselgren-b hasselgren-c hasselgren-d hasselgren-e hasselgren-f \
  msaa-2 msaa-4 msaa-8 msaa-16 --profile "$img/profile.svg" >/dev/null
"$aapat" show flipquad -o "$img/flipquad.svg" >/dev/null
"$aapat" figure10 --objective laine-aila --starts 256 --csv docs/figure10.csv --svg "$img/figure10.svg" > docs/figure10.txt
"$aapat" enumerate --objective laine-aila --optimize --csv docs/enumerate.csv --gallery "$img/enumerate-gallery.svg" > docs/enumerate.txt
# Spectra: 1024 points, 256 x 256 frequencies, 10 realizations (Halton is deterministic).
for g in jittered poisson best-candidate halton; do
  "$aapat" spectrum "$g" --n 1024 --size 256 --realizations 10 -o "$img/spectrum-$g.png" \
    --csv "docs/spectrum-$g.csv" --svg "$img/radial-$g.svg" >/dev/null
done
# Goss & Wu Figure 8: 1D Poisson disk against uniform jitter, 7488 samples, 128K frequencies.
"$aapat" spectrum --1d poisson,jittered --n 7488 --frequencies 131072 --max-frequency 4 \
  --svg "$img/spectrum-1d.svg" >/dev/null
# Goss & Wu Figs. 9-20: regular / N-queens / jittered at 4 and 16 samples x box / tent / Gaussian 1/2.
"$aapat" render checkerboard --grid --size 192x128 -o "$img/sheet-gosswu-checkerboard.png" \
  --table docs/sheet-gosswu-checkerboard.md >/dev/null
# Hasselgren Fig. 5: the spiral with the sample-sharing schemes, own weights and a tent.
"$aapat" render spiral --grid --size 96x96 --zoom 2 --rows centroid diagonal-hasselgren \
  hasselgren-a hasselgren-b hasselgren-c hasselgren-d hasselgren-e quincunx-hasselgren \
  hasselgren-f --columns weights tent -o "$img/sheet-hasselgren-spiral.png" \
  --table docs/sheet-hasselgren-spiral.md >/dev/null
# CS4620 Lecture 23: texture minification on the textured checkerboard, multisampled with
# point, bilinear, trilinear and anisotropic lookups against supersampling at 4 and 16 samples.
"$aapat" render checkerboard --texture checker --grid --size 256x160 --reference-filter gaussian \
  --rows "msaa-4+mode=multisample+texture-filter=nearest+label=MSAA 4, point" \
  "msaa-4+mode=multisample+texture-filter=bilinear+label=MSAA 4, bilinear" \
  "msaa-4+mode=multisample+texture-filter=trilinear+label=MSAA 4, trilinear" \
  "msaa-4+mode=multisample+texture-filter=aniso:probes=8+label=MSAA 4, aniso 8" \
  "msaa-4+label=SSAA 4" "msaa-16+label=SSAA 16" \
  --columns gaussian -o "$img/sheet-texture-minification.png" \
  --table docs/sheet-texture-minification.md >/dev/null
# Pelikan: adaptive refinement against uniform jitter, with the refinement maps.
for scene in spiral circles checkerboard; do
  "$aapat" render "$scene" --grid --size 128x128 --rows jittered@4 jittered@9 jittered@16 \
    "jittered@4+adaptive=neighbours+threshold=0.05+per-square=3+max-depth=2+label=adaptive A" \
    "jittered@4+adaptive=neighbours+threshold=0.05+per-square=4+max-depth=3+label=adaptive B" \
    --columns box "box+show=map+label=samples" --reference-filter box \
    -o "$img/sheet-adaptive-$scene.png" \
    --table "docs/sheet-adaptive-$scene.md" >/dev/null
done
# Which objective predicts rendered error: 30+ patterns at 2, 4 and 8 samples per pixel.
"$aapat" study --budgets 2,4,8 --patterns 30 --table docs/study-correlations.md \
  --csv docs/study-correlations.csv --html docs/study-report.html >/dev/null
# The same study on real models in colour: the six mesh views at 128x128
# (data/mesh-views, Debian's assimp-testmodels; docs/perceptual.md).
# Run from the root, so that the tables name the views by their relative paths.
docs_out=$(pwd)
(cd "$root" && "$aapat" study --budgets 2,4,8 --patterns 30 --size 128 \
  --scenes data/mesh-views/*.json --table "$docs_out/docs/study-meshes.md" \
  --csv "$docs_out/docs/study-meshes.csv" >/dev/null)
# The aapat catalog against the published and standard patterns of each cost.
AAPAT="$aapat" "$root/scripts/catalog-table.sh" docs/catalog-table.md >/dev/null
# Jitter and alternating-MSAA sequences under box, EMA and EMA + resolve, and rendered TAA.
AAPAT="$aapat" "$root/scripts/temporal-table.sh" docs/temporal-table.md >/dev/null
"$aapat" hardware-table --objective laine-aila > docs/hardware-table.md
# Engine TAA (docs/temporal.md): the optimized jitters under every preset and
# ratio, and a moving spiral's last frame under two presets, the engine's
# own jitter beside aapat's.
AAPAT="$aapat" "$root/scripts/engine-taa-table.sh" docs/engine-taa-table.md >/dev/null
taa_tmp=$(mktemp -d)
for run in "fsr2 1.5 halton aapat-upscale-1.5" "ue4 1 ue4-halton:frames=8 aapat-taa-8"; do
  read -r preset ratio own ours <<<"$run"
  for seq in "$own" "$ours"; do
    name=$(echo "$seq" | cut -d: -f1)
    "$aapat" animate spiral --taa "$preset" --ratio "$ratio" --sequence "$seq" \
      --motion pan:dx=0.37,dy=0.21 --size 96 --frames 8 --warmup 40 --reference-samples 16 \
      --frames-dir "$taa_tmp/$preset-$name" >/dev/null
    cp "$taa_tmp/$preset-$name/frame-0007.png" "$img/engine-taa-$preset-$name.png"
  done
done
rm -rf "$taa_tmp"
# FLIP (docs/perceptual.md): msaa-8 and aapat-8 on the zone plate against its reference.
flip_tmp=$(mktemp -d)
"$aapat" render zoneplate --pattern msaa-8 --size 128x128 --reference-samples 256 --no-cache \
  -o "$flip_tmp/msaa-8.png" --reference "$flip_tmp/reference.png" >/dev/null
"$aapat" render zoneplate --pattern aapat-8 --size 128x128 -o "$flip_tmp/aapat-8.png" >/dev/null
{
  echo "pattern,rmse,flip,flip_weighted_median"
  for p in msaa-8 aapat-8; do
    "$aapat" diff "$flip_tmp/reference.png" "$flip_tmp/$p.png" --map "$img/flip-zoneplate-$p.png" --json |
      python3 -c "import json,sys; d=json.load(sys.stdin); print('$p,%.3f,%.6f,%.4f' % (d['rmse'], d['flip'], d['flip_weighted_median']))"
  done
} > docs/flip-zoneplate.csv
# The same pair on a mesh view (docs/perceptual.md): FLIP maps side by side.
view="$root/data/mesh-views/truck-three-quarter.json"
"$aapat" render "$view" --pattern msaa-8 --size 128x128 --reference-samples 256 \
  -o "$flip_tmp/mesh-msaa-8.png" --reference "$flip_tmp/mesh-reference.png" >/dev/null
"$aapat" render "$view" --pattern aapat-8 --size 128x128 -o "$flip_tmp/mesh-aapat-8.png" >/dev/null
cp "$flip_tmp/mesh-reference.png" "$img/flip-mesh-reference.png"
{
  echo "pattern,rmse,flip,flip_weighted_median"
  for p in msaa-8 aapat-8; do
    cp "$flip_tmp/mesh-$p.png" "$img/flip-mesh-$p-image.png"
    "$aapat" diff "$flip_tmp/mesh-reference.png" "$flip_tmp/mesh-$p.png" --map "$img/flip-mesh-$p.png" --json |
      python3 -c "import json,sys; d=json.load(sys.stdin); print('$p,%.3f,%.6f,%.4f' % (d['rmse'], d['flip'], d['flip_weighted_median']))"
  done
} > docs/flip-mesh.csv
rm -rf "$flip_tmp"
# Every registry of specs, as aapat list prints it (the same entries the parsers use).
"$aapat" list > docs/registry.txt
# Standard input set between two marker lines of a committed doc, the prose
# around them kept: splice DOC BEGIN-MARKER END-MARKER.
splice() {
  python3 -c '
import sys
doc = open(sys.argv[1]).read()
begin, end = sys.argv[2] + "\n", sys.argv[3] + "\n"
head, rest = doc.split(begin)
sys.stdout.write(head + begin + sys.stdin.read() + end + rest.split(end, 1)[1])
' "$root/$1" "$2" "$3" > "$1.new"
  mv "$1.new" "$1"
}
# docs/limits.md's table is `aapat limits --markdown` (the library's table of limits).
"$aapat" limits --markdown |
  splice docs/limits.md "<!-- the table: aapat limits --markdown -->" "<!-- end of the table -->"
# docs/cli.md's option tables are `aapat list --modes` (the tables the commands enforce).
"$aapat" list --modes |
  splice docs/cli.md "<!-- the tables: aapat list --modes -->" "<!-- end of the tables -->"
echo "figures written under docs/"
