#!/bin/bash
# firn's step against the speed yardstick (../shared/bench/baseline_mpm.cpp, plain OpenMP MLS-MPM,
# built here with g++ -O3 -march=native -fopenmp) on cube_drop (512,000 particles, float), run
# alternately REPS times in one go; prints each run, both medians, their ratio and the CPU model.
# Usage: bench/against_yardstick.sh [FIRN] [REPS] [THREADS] [STEPS]
set -euo pipefail
FIRN=${1:-build/release/firn}
REPS=${2:-3}
THREADS=${3:-2}
STEPS=${4:-100}
SOURCE=${YARDSTICK_SOURCE:-$(dirname "$0")/../../shared/bench/baseline_mpm.cpp}
yardstick=$(mktemp -d)/baseline_mpm
trap 'rm -rf "$(dirname "$yardstick")"' EXIT
g++ -O3 -march=native -fopenmp "$SOURCE" -o "$yardstick"
echo "cpu $(lscpu | sed -n 's/^Model name: *//p'), threads $THREADS, $STEPS steps"
for _ in $(seq "$REPS"); do
  echo "firn $("$FIRN" bench step --problem cube_drop --steps "$STEPS" --threads "$THREADS" | awk '$1 == "particle_steps_per_second" {print $2}')"
  echo "yardstick $(OMP_NUM_THREADS=$THREADS "$yardstick" 100 "$STEPS" | awk '$1 == "particle_steps_per_second" {print $2}')"
done | python3 -c '
import collections, statistics, sys
runs = collections.defaultdict(list)
for line in sys.stdin:
    print(line, end="", flush=True)  # each run as it ends
    name, rate = line.split()
    runs[name].append(float(rate))
firn, yard = statistics.median(runs["firn"]), statistics.median(runs["yardstick"])
print("median firn %.4g yardstick %.4g ratio %.2f" % (firn, yard, firn / yard))
'
