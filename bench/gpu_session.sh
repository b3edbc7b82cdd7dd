#!/bin/bash
# Every GPU measurement issue 14 asks for, in one go, for a machine with an NVIDIA GPU and a CUDA
# build of firn (docs/cuda.md): the CUDA test instances, firn verify on the GPU, cube_drop at 512k
# and 4.1M particles and the full-resolution snowball pair twice each (the state hash must
# repeat), every scene's preview, the full-resolution tire over 0.25 s with the launch profile,
# a rendered preview (which EGL platform drew it) and the kernel microbenchmarks. Each step's
# output goes to OUT/NN_name.log; OUT/summary.txt collects the lines to read first. A step that
# fails is recorded and the next one runs.
# Usage: bench/gpu_session.sh FIRN FIRN_TESTS BENCH_KERNELS OUT
# (FIRN_TESTS and BENCH_KERNELS may be "-" to skip them.)
set -uo pipefail
FIRN=$1
TESTS=$2
KERNELS=$3
OUT=$4
SCENES=$(cd "$(dirname "$0")/../scenes" && pwd)
mkdir -p "$OUT"
summary=$OUT/summary.txt
step=0

# run NAME COMMAND...: runs it with its output in OUT/NN_NAME.log ($log), its exit status and wall
# time (and where it failed, its last line) in the summary.
log=
run() {
  local name=$1
  shift
  step=$((step + 1))
  log=$(printf '%s/%02d_%s.log' "$OUT" "$step" "$name")
  local start=$SECONDS
  "$@" > "$log" 2>&1
  local rc=$?
  echo "$name: rc $rc, $((SECONDS - start)) s" >> "$summary"
  [ "$rc" = 0 ] || tail -n 1 "$log" | sed 's/^/  /' >> "$summary"
}

# scene_summary DIR: the lines of a run's summary.json worth reading.
scene_summary() {
  [ -f "$1/summary.json" ] || return 0
  python3 -c 'import json, sys; d = json.load(open(sys.argv[1] + "/summary.json")); print(" ", d["status"], d["particles"], "particles", d["steps"], "steps", round(d["step_seconds"], 2), "s stepping", round(d["wall_seconds"], 2), "s wall", d["state_hash"])' "$1" >> "$summary" 2>&1
}

{
  date -u
  nvidia-smi -L 2>/dev/null || echo "no nvidia-smi"
  lscpu | sed -n 's/^Model name: *//p'
} > "$summary"

[ "$TESTS" != - ] && run tests_cuda "$TESTS" --gtest_filter='*Cuda*'
run verify_cuda "$FIRN" verify incline_sliding incline_rolling vibrating_bar --backend cuda
for i in 1 2 3; do
  run "cube512k_$i" "$FIRN" bench step --problem cube_drop --steps 50 --backend cuda
  grep -E "particle_steps_per_second|state_hash" "$log" | tr '\n' ' ' | sed 's/^/  /;s/$/\n/' >> "$summary"
done
for i in 1 2; do
  run "cube4m_$i" "$FIRN" run "$SCENES/cube_drop.toml" --backend cuda --set simulation.dx=0.005 \
    --set "simulation.end_time=5 ms" --out "$OUT/cube4m_$i"
  scene_summary "$OUT/cube4m_$i"
  run "snowball_pair_$i" "$FIRN" run "$SCENES/snowball_pair.toml" --backend cuda --set "simulation.end_time=10 ms" \
    --out "$OUT/snowball_pair_$i"
  scene_summary "$OUT/snowball_pair_$i"
done
for s in "$SCENES"/*.toml; do
  n=$(basename "$s" .toml)
  preview=--preview
  [ "$n" = tire_inflated_on_ground ] && preview=  # its pressure needs 8 particles per cell
  run "preview_$n" "$FIRN" run "$s" $preview --backend cuda --set "simulation.end_time=5 ms" --out "$OUT/preview_$n"
  scene_summary "$OUT/preview_$n"
done
run tire_full "$FIRN" run "$SCENES/tire_on_snow.toml" --backend cuda --profile --out "$OUT/tire_full"
scene_summary "$OUT/tire_full"
grep -E "launch" "$log" | head -12 >> "$summary"
run render "$FIRN" run "$SCENES/snowball_pair.toml" --preview --backend cuda --render spheres \
  --set "simulation.end_time=20 ms" --out "$OUT/render"
grep -iE "egl|osmesa|opengl" "$log" | head -3 >> "$summary"
[ "$KERNELS" != - ] && run kernels "$KERNELS" --benchmark_filter=cuda
cat "$summary"
