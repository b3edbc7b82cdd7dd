#!/bin/bash
# The thesis' hyperelastic-plastic scenes against cube_drop (issue 15): particle-steps per second
# of the step loop (summary.json's step_seconds) for scenes/tire_on_snow.toml at full resolution
# over 5 ms and scenes/snowball_pair.toml at full resolution (10 ms), beside `firn bench step
# --problem cube_drop`, run alternately REPS times; prints medians and each scene's share of
# cube_drop's rate.
# Usage: bench/plastic_scene_rates.sh [FIRN] [REPS] [THREADS]
set -euo pipefail
FIRN=${1:-build/release/firn}
REPS=${2:-3}
THREADS=${3:-2}
SCENES=$(dirname "$0")/../scenes
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rate() { python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(d["particles"] * d["steps"] / d["step_seconds"])' "$1/summary.json"; }
echo "cpu $(lscpu | sed -n 's/^Model name: *//p'), threads $THREADS"
for _ in $(seq "$REPS"); do
  echo "cube_drop $("$FIRN" bench step --problem cube_drop --threads "$THREADS" | awk '$1 == "particle_steps_per_second" {print $2}')"
  "$FIRN" run "$SCENES/tire_on_snow.toml" --set "simulation.end_time=5 ms" --threads "$THREADS" --out "$out/tire" > /dev/null
  echo "tire_on_snow $(rate "$out/tire")"
  "$FIRN" run "$SCENES/snowball_pair.toml" --threads "$THREADS" --out "$out/pair" > /dev/null
  echo "snowball_pair $(rate "$out/pair")"
done | python3 -c '
import collections, statistics, sys
runs = collections.defaultdict(list)
for line in sys.stdin:
    print(line, end="", flush=True)  # each run as it ends
    name, rate = line.split()
    runs[name].append(float(rate))
cube = statistics.median(runs["cube_drop"])
for name, rates in runs.items():
    m = statistics.median(rates)
    print("median %s %.4g (%.0f%% of cube_drop)" % (name, m, 100 * m / cube))
'
