#!/usr/bin/env bash
# The same command gives the same files on one process (every core) and
# across MPI ranks (mpirun -np 1, 2 and 3, one or two threads a rank; other
# thread counts on one process are in the unit tests), a checkpointed run
# that is killed resumes to the same files (on one process, and across ranks
# with another rank count), a rank that dies fails the run with a message and
# no output, and so does an error on one rank only (docs/cluster.md). Usage: scripts/test-cluster.sh AAPAT_BINARY
# Exit 77 (skipped) without mpirun or without MPI in the binary.
set -uo pipefail
aapat=$(realpath "$1")
command -v mpirun >/dev/null || { echo "mpirun not found: skipped"; exit 77; }
ldd "$aapat" | grep libmpi >/dev/null || { echo "aapat built without MPI: skipped"; exit 77; }
# Root in containers and CI; more ranks than cores on a 2-core machine.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
export AAPAT_CACHE="$work/cache"
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

# before_dashes ARRAY ARGS...: ARRAY gets ARGS up to the first "--"; the
# caller then shifts ${#ARRAY[@]} + 1 to reach what follows it.
before_dashes() {
  local -n into=$1
  shift
  into=()
  while [ "$1" != "--" ]; do
    into+=("$1")
    shift
  done
}

# run NAME LAUNCH... -- ARGS...: the command's outputs go to NAME/ (stdout as
# stdout.txt); LAUNCH is empty (one process) or an mpirun prefix.
run() {
  local name=$1
  shift
  local launch
  before_dashes launch "$@"
  shift $((${#launch[@]} + 1))
  mkdir -p "$name"
  (cd "$name" && "${launch[@]}" "$aapat" "$@" >stdout.txt 2>stderr.txt) ||
    { fail "$name exited $?: $(tail -3 "$name/stderr.txt")"; return; }
}
same() {  # same REFERENCE OTHER FILE...
  local ref=$1 other=$2
  shift 2
  for f in "$@"; do
    cmp -s "$ref/$f" "$other/$f" || fail "$other/$f differs from $ref/$f"
  done
}
check() {  # check NAME FILES... -- ARGS...: every scale against one process
  local name=$1
  shift
  local files
  before_dashes files "$@"
  shift $((${#files[@]} + 1))
  run "$name-ref" -- "$@"
  run "$name-np1" mpirun -np 1 -- "$@"
  run "$name-np2" mpirun -np 2 -- --threads 1 "$@"
  run "$name-np3" mpirun -np 3 -- --threads 1 "$@"
  run "$name-np3t2" mpirun -np 3 -- --threads 2 "$@"
  for scale in np1 np2 np3 np3t2; do same "$name-ref" "$name-$scale" "${files[@]}"; done
  echo "$name: the same files at every scale (${SECONDS} s into the test)"
}

check optimize best.json -- optimize --family 'P(4,4,4)' --starts 24 \
  --seed 5 --objective laine-aila -o best.json
check optimize-lattice best.json -- optimize --family 'P(1,1,4)' --starts 6 --lattice 16 --seed 3 \
  --objective laine-aila -o best.json
check enumerate table.csv gallery.svg stdout.txt -- enumerate --cost 1.25,1.5 --optimize --starts 3 \
  --objective laine-aila --csv table.csv --gallery gallery.svg
check reference stdout.txt reference.png error.png -- render circles --pattern msaa-4 --size 48x40 \
  --reference-samples 64 --no-cache --json --reference reference.png --error error.png -o render.png
check table3 stdout.txt -- table3 --patterns 40 --iterations 30 --json
check figure10 f10.csv -- figure10 --starts 2 --csv f10.csv
# (hardware-table is made of the same searches as optimize and
# optimize-lattice; checked by hand, 12 s here: docs/cluster.md.)
check sequence best.json -- optimize --sequence 8 --starts 6 --seed 4 -o best.json
check study table.md table.csv -- study --budgets 4 --patterns 8 --scenes circles spiral --size 24 \
  --frames 1 --starts 1 --resamples 50 --no-cache --table table.md --csv table.csv

# A run killed midway resumes from its checkpoint to the same files.
long=(optimize --family 'P(4,4,4)' --starts 1000 --seed 9 --objective laine-aila -o best.json)
records() {
  local n
  n=$(grep -c '^item ' "$1" 2>/dev/null)
  echo "${n:-0}"
}
killed_run() {  # killed_run NAME SIGNAL LAUNCH...: start, wait for 20 finished items, kill
  local name=$1 signal=$2
  shift 2
  mkdir -p "$name"
  (cd "$name" && exec "$@" "$aapat" --checkpoint ck "${long[@]}" >/dev/null 2>&1) &
  local pid=$!
  for _ in $(seq 600); do
    [ "$(records "$name/ck")" -ge 20 ] && break
    sleep 0.05
  done
  kill "-$signal" "$pid" 2>/dev/null
  pkill "-$signal" -f -- "--checkpoint ck optimize" 2>/dev/null  # the ranks too, at once
  wait "$pid" 2>/dev/null
  [ -e "$name/best.json" ] && fail "$name: the killed run left best.json"
  local done_items
  done_items=$(records "$name/ck")
  [ "$done_items" -ge 20 ] && [ "$done_items" -lt 1000 ] ||
    fail "$name: $done_items items in the checkpoint when killed"
  echo "$name: killed (SIG$signal) with $done_items of 1000 starts in the checkpoint"
}
run resume-ref -- "${long[@]}"
killed_run resume-local KILL
run resume-local -- --checkpoint ck "${long[@]}"
grep -q "resuming from ck" resume-local/stderr.txt || fail "resume-local: no word of resuming"
same resume-ref resume-local best.json
killed_run resume-mpi KILL mpirun -np 2
run resume-mpi mpirun -np 3 -- --threads 1 --checkpoint ck "${long[@]}"
grep -q "resuming from ck" resume-mpi/stderr.txt || fail "resume-mpi: no word of resuming"
same resume-ref resume-mpi best.json
echo "checkpoint: killed runs resumed to the same files"

# A rank that dies ends the run: non-zero exit, mpirun names the rank, no output.
mkdir -p dies
(cd dies && exec mpirun -np 3 "$aapat" --threads 1 "${long[@]}" >stdout.txt 2>stderr.txt) &
pid=$!
victim=""
for _ in $(seq 200); do
  for p in $(pgrep -f -- "--starts 1000 --seed 9"); do
    grep -qz '^OMPI_COMM_WORLD_RANK=2$' "/proc/$p/environ" 2>/dev/null && victim=$p
  done
  [ -n "$victim" ] && break
  sleep 0.05
done
sleep 0.5
[ -n "$victim" ] && kill -9 "$victim"
wait "$pid"
status=$?
[ "$status" -ne 0 ] || fail "dies: mpirun exited 0 after rank 2 was killed"
grep -q "rank 2" dies/stderr.txt || fail "dies: the message does not name rank 2: $(cat dies/stderr.txt)"
[ -e dies/best.json ] && fail "dies: best.json written"
echo "a dead rank: exit $status, $(grep -m1 'rank 2' dies/stderr.txt)"

# An error on one rank only (MPMD: rank 1 gets other arguments) fails the
# command on every rank: rank 0 names the rank, no output, exit 1.
one_rank_fails() {  # one_rank_fails NAME EXPECTED_STATUS ARGS_OF_RANK_0 -- ARGS_OF_RANK_1
  local name=$1 expected=$2
  shift 2
  local first
  before_dashes first "$@"
  shift $((${#first[@]} + 1))
  mkdir -p "$name"
  (cd "$name" && timeout 120 mpirun -np 1 "$aapat" "${first[@]}" : -np 1 "$aapat" "$@" \
    >stdout.txt 2>stderr.txt)
  local status=$?
  [ "$status" -eq "$expected" ] || fail "$name: exit $status, expected $expected: $(head -3 "$name/stderr.txt")"
  [ -e "$name/best.json" ] && fail "$name: best.json written"
  echo "$name: exit $status, $(grep -m1 'aapat: error' "$name/stderr.txt")"
}
one_rank_fails parse-error-on-one-rank 1 optimize --family 'P(1,1,4)' --starts 8 --objective laine-aila -o best.json -- \
  optimize --family 'P(1,1,4)' --starts 8 --objective laine-aila -o best.json --no-such-option
one_rank_fails fails-before-items 1 optimize --family 'P(4,4,4)' --starts 400 --objective laine-aila -o best.json -- \
  optimize --family 'P(4,4,4)' --starts 400 --objective laine-aila --seeds nonsense -o best.json
grep -q "rank 1: --seeds" fails-before-items/stderr.txt ||
  fail "fails-before-items: rank 1's error not reported: $(cat fails-before-items/stderr.txt)"

[ "$failures" -eq 0 ] && echo "cluster: all checks passed"
exit $((failures > 0))
