#!/usr/bin/env bash
# Times `skytrack track` on a generated load: N point targets and C clutter plots per scan
# (snapshot 3-D radar, 150 km, 4 s, Pd 0.9, 30 scans), printing the tracker's own summary
# (per-batch latency p50/p99/max, wall time, peak RSS).
# Usage: tools/experiments/track-load.sh [targets] [clutter] [profile.yaml] [sector_deg]
# (sector_deg: the targets bunched into that many degrees of bearing; default 360.)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
targets=${1:-500}
clutter=${2:-1000}
profile=${3:-}
sector=${4:-360}
out="$root/out/experiments/track-load"
mkdir -p "$out"
scenario="$out/load_${targets}_${clutter}.yaml"
python3 "$root/tools/experiments/load-scenario.py" "load_${targets}_${clutter}" "$targets" "$clutter" \
  116 4.0 "$sector" >"$scenario"
"$skytrack" simulate --scenario "$scenario" --plots "$out/load.plots.jsonl" --truth "$out/load.truth.jsonl"
args=(track --plots "$out/load.plots.jsonl" --out "$out/load.tracks.jsonl" --quiet)
[ -n "$profile" ] && args+=(--profile "$profile")
"$skytrack" "${args[@]}"
