#!/usr/bin/env bash
# Whole commands with 1 thread and with every core (aapat --threads N), the
# median wall time of three runs each: the table of docs/benchmarks.md
# "Which commands use every core". Run from the repository root after
# building the release preset.
set -euo pipefail
aapat=${AAPAT:-build/release/aapat}
cores=$(nproc)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
median_time() {
  local times=()
  for _ in 1 2 3; do
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null 2>&1
    end=$(date +%s.%N)
    times+=("$(echo "$end - $start" | bc -l)")
  done
  printf '%s\n' "${times[@]}" | sort -g | sed -n 2p
}
run() {
  local label=$1
  shift
  local one all
  one=$(median_time "$aapat" --threads 1 "$@")
  all=$(median_time "$aapat" --threads 0 "$@")
  printf '| `%s` | %.2f s | %.2f s | %.2fx |\n' "$label" "$one" "$all" "$(echo "$one / $all" | bc -l)"
}
echo "| command | 1 thread | $cores threads | speed-up |"
echo "| --- | ---: | ---: | ---: |"
run "optimize --family 'P(4,4,4)' --starts 64" optimize --family 'P(4,4,4)' --starts 64 --seed 1 -o "$scratch/p.json"
run "figure10 --starts 64" figure10 --starts 64
run "enumerate --optimize" enumerate --optimize
run "table3" table3
run "hardware-table" hardware-table
run "spectrum jittered --n 4096 --size 512" spectrum jittered --n 4096 --size 512
run "spectrum halton --n 65536 --size 1024 --fast" spectrum halton --n 65536 --size 1024 --fast
run "discrepancy halton --n 65536 --measure all" discrepancy halton --n 65536 --measure all
run "render checkerboard --grid --size 192x128 --no-cache" render checkerboard --grid --size 192x128 --no-cache -o "$scratch/g.png"
run "table2 --no-cache" table2 --no-cache
