#!/usr/bin/env bash
# Runs the scene fuzzer (tests/fuzz/fuzz_scene.cpp) for SECONDS on one core, seeded from the
# shipped scenes, the malformed-scene suite and tests/fuzz/seeds/ (values with units, --set lines).
# The corpus it grows is kept in CORPUS (default build/fuzz/corpus) for the next run; a crash, a
# hang (over 10 s for one input), a leak or a sanitizer report stops it with a non-zero exit status
# and the input in build/fuzz/findings/.
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
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=16384 -print_final_stats=1 \
  -artifact_prefix=build/fuzz/findings/ "$corpus" "$seeds"
