#!/usr/bin/env bash
# Times `skytrack track` on a generated load: N point targets and C clutter plots per scan
# (snapshot 3-D radar, 150 km, 4 s, Pd 0.9, 30 scans), printing the tracker's own summary
# (per-batch latency p50/p99/max, wall time, peak RSS).
# Usage: tools/experiments/track-load.sh [targets] [clutter] [profile.yaml]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
targets=${1:-500}
clutter=${2:-1000}
profile=${3:-}
out="$root/out/experiments/track-load"
mkdir -p "$out"
scenario="$out/load_${targets}_${clutter}.yaml"
python3 - "$targets" "$clutter" > "$scenario" <<'PY'
import math, random, sys
targets, clutter = int(sys.argv[1]), int(sys.argv[2])
rng = random.Random(7)
print(f"""scenario: {{name: load_{targets}_{clutter}, dimensions: 3, duration: 116, seed: 1}}
platform: {{position: [0, 0, 20]}}
sensor:
  scan_period: 4.0
  detection_probability: 0.9
  max_range: 150000
  sigma: {{range: 30.0, azimuth: 0.002, elevation: 0.003}}
clutter: {{mean: {clutter}, range: [5000, 150000], elevation: [0.0, 0.1]}}
targets:""")
for i in range(targets):
    r, b = 20000 + 120000 * rng.random(), 2 * math.pi * rng.random()
    h, v = 2 * math.pi * rng.random(), 150 + 150 * rng.random()
    print(f"  - {{id: {i}, position: [{r*math.sin(b):.1f}, {r*math.cos(b):.1f}, "
          f"{1000 + 9000*rng.random():.1f}], velocity: [{v*math.sin(h):.2f}, {v*math.cos(h):.2f}, 0]}}")
PY
"$skytrack" simulate --scenario "$scenario" --plots "$out/load.plots.jsonl" --truth "$out/load.truth.jsonl"
args=(track --plots "$out/load.plots.jsonl" --out "$out/load.tracks.jsonl" --quiet)
[ -n "$profile" ] && args+=(--profile "$profile")
"$skytrack" "${args[@]}"
