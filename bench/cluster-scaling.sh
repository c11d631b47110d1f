#!/usr/bin/env bash
# Strong scaling of work items across MPI ranks on this machine (issue 17):
# an enumeration and a large multi-start, on one process with one thread and
# under mpirun with 1 and 2 ranks of one thread each, each run REPEAT times
# (best wall time kept), outputs checked identical. Prints a markdown table
# and each run's rank report (busy time per rank, items, the longest item),
# the inputs of the scaling model in docs/cluster.md.
# Usage: bench/cluster-scaling.sh AAPAT_BINARY [REPEAT]
set -euo pipefail
aapat=$(realpath "$1")
repeat=${2:-3}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
jobs=(
  "enumerate|enumerate --optimize --starts 128 --csv out.csv|out.csv"
  "multi-start|optimize --family P(4,4,4) --starts 2000 --seed 1 -o out.json|out.json"
)
best() {  # best LABEL LAUNCH... -- ARGS: the best wall time of REPEAT runs
  local label=$1
  shift
  local launch=()
  while [ "$1" != "--" ]; do launch+=("$1"); shift; done
  shift
  local t best_t=""
  for _ in $(seq "$repeat"); do
    local t0 t1
    t0=$(date +%s.%N)
    "${launch[@]}" "$aapat" --threads 1 "$@" >/dev/null 2>"$label.err"
    t1=$(date +%s.%N)
    t=$(echo "$t1 - $t0" | bc -l)
    if [ -z "$best_t" ] || [ "$(echo "$t < $best_t" | bc -l)" = 1 ]; then best_t=$t; fi
  done
  printf '%.2f' "$best_t"
}
echo "| job | 1 process | mpirun -np 1 | mpirun -np 2 | speed-up (1 process to 2 ranks) |"
echo "| --- | --- | --- | --- | --- |"
for job in "${jobs[@]}"; do
  IFS='|' read -r name args out <<<"$job"
  read -ra argv <<<"$args"
  t1=$(best "$name-1" -- "${argv[@]}"); cp "$out" ref.out
  tn1=$(best "$name-np1" mpirun -np 1 -- "${argv[@]}"); cmp -s ref.out "$out" || echo "np1 differs"
  tn2=$(best "$name-np2" mpirun -np 2 -- "${argv[@]}"); cmp -s ref.out "$out" || echo "np2 differs"
  echo "| $name (\`$args\`) | $t1 s | $tn1 s | $tn2 s | $(echo "scale=2; $t1 / $tn2" | bc -l) |"
  reports+=("$name, 2 ranks: $(grep 'ranks,' "$name-np2.err")")
done
echo
printf '%s\n' "${reports[@]}"
