#!/bin/bash
# What skipping unused work saves (docs/performance.md): `firn bench step` on cube_drop (512,000
# particles, float) with, in turn, each thing the problem does not need added back, and the energy
# budget that `firn run` keeps, run interleaved REPS times; prints each variant's median
# particle-steps/s, its ratio to the plain problem, bytes per particle and grid memory.
# EXTRA is passed to every run, e.g. "--material thesis_hard_snow" for the plastic path (with
# STEPS of 300 or more, so that the cube has landed and yields for most of them).
# Usage: bench/pay_for_use.sh [FIRN] [REPS] [STEPS] [THREADS] [EXTRA]
set -euo pipefail
FIRN=${1:-build/release/firn}
REPS=${2:-5}
STEPS=${3:-30}
THREADS=${4:-2}
read -r -a extra <<< "${5:-}"
variants=(
  "plain|"
  "plastic_state|--enable alpha --enable Jp"
  "rest_positions|--enable x0"
  "idle_materials|--idle-materials 8"
  "domain_x4|--domain-scale 4"
  "pic|--transfer pic"
  "flip|--transfer flip"
  "energy_budget|--energy-budget"
)
for _ in $(seq "$REPS"); do
  for v in "${variants[@]}"; do
    name=${v%%|*}
    read -r -a args <<< "${v#*|}"
    "$FIRN" bench step --steps "$STEPS" --threads "$THREADS" "${extra[@]}" "${args[@]}" |
      awk -v name="$name" '{f[$1] = $2} END {print name, f["particle_steps_per_second"], f["bytes_per_particle"], f["grid_memory_mb"]}'
  done
done | python3 -c '
import collections, statistics, sys
runs, info = collections.defaultdict(list), {}
for line in sys.stdin:
    name, rate, size, grid = line.split()
    runs[name].append(float(rate))
    info[name] = (size, grid)
plain = statistics.median(runs["plain"])
print("variant median_particle_steps_per_second ratio_to_plain bytes_per_particle grid_memory_mb")
for name, rates in runs.items():
    m = statistics.median(rates)
    print(name, "%.4g" % m, "%.3f" % (m / plain), *info[name])
'
