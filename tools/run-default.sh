#!/usr/bin/env bash
# The README's first command: build, simulate the shipped default scenario and evaluate it.
# (The tracker and the daemon join this chain as they land.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
skytrack="${SKYTRACK_BUILD_DIR:-$root/build}/tools/skytrack/skytrack"
out="$root/out"
mkdir -p "$out"
scenario="${1:-$root/config/scenarios/default.yaml}"
"$skytrack" simulate --scenario "$scenario" --plots "$out/default.plots.jsonl" \
  --truth "$out/default.truth.jsonl"
# No tracker yet: score the truth against itself to check the chain (GOSPA must be 0).
"$skytrack" eval --truth "$out/default.truth.jsonl" --tracks "$out/default.truth.jsonl" \
  --plot "$out/default.svg"
echo "picture: $out/default.svg"
