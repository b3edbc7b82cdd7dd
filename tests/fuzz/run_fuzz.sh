#!/usr/bin/env bash
# Runs the scene fuzzer (tests/fuzz/fuzz_scene.cpp) for SECONDS on one core, seeded from the
# shipped scenes, the malformed-scene suite and tests/fuzz/seeds/ (values with units, --set lines).
# The corpus it grows is kept in CORPUS (default build/fuzz/corpus) for the next run. A crash, a
# leak, a sanitizer report or a hang stops it with a non-zero exit status and the input in
# build/fuzz/findings/. A hang is one input running over 60 s of wall time: generous, because a
# niced run on a busy machine can stall for seconds through no fault of its own (a 10 s limit
# once reported an input that runs in 0.3 s).
# Usage: tests/fuzz/run_fuzz.sh FUZZER SECONDS [CORPUS]
set -euo pipefail
fuzzer=$(realpath "$1")
seconds=$2
cd "$(dirname "$0")/../.."
corpus=${3:-build/fuzz/corpus}
mkdir -p "$corpus" build/fuzz/findings
seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT
for f in scenes/*.toml tests/scenes/malformed/*.toml; do cp "$f" "$seeds/$(basename "$(dirname "$f")")_$(basename "$f")"; done
cp tests/fuzz/seeds/* "$seeds/"
"$fuzzer" -max_total_time="$seconds" -timeout=60 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
  -artifact_prefix=build/fuzz/findings/ "$corpus" "$seeds"
