#!/usr/bin/env bash
# The README's first command: build, simulate the shipped default scenario, track it with the
# default profile and evaluate the tracks against the truth. (The daemon joins this chain when
# it lands: replay over DDS instead of the offline run.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
skytrack="${SKYTRACK_BUILD_DIR:-$root/build}/tools/skytrack/skytrack"
out="$root/out"
mkdir -p "$out"
scenario="${1:-$root/config/scenarios/default.yaml}"
"$skytrack" simulate --scenario "$scenario" --plots "$out/default.plots.jsonl" \
  --truth "$out/default.truth.jsonl"
"$skytrack" track --plots "$out/default.plots.jsonl" --out "$out/default.tracks.jsonl" --quiet
# Cut-off 500 m: a few times the height error of a 3 mrad elevation at 40-60 km.
"$skytrack" eval --truth "$out/default.truth.jsonl" --tracks "$out/default.tracks.jsonl" \
  --cutoff 500 --plot "$out/default.svg"
echo "picture: $out/default.svg"
