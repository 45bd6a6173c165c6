#!/usr/bin/env bash
# Plot floods through `skytrack track` (docs/hardening.md): one aircraft tracked by a
# snapshot radar every 4 s for 14 scans while, from scan 4 to 9, either a cloud of N plots
# within about 150 m of one point (chaff, a jammer's false plots, a swarm too dense to
# resolve) or N plots spread at random over a 200 km disc (a broken extractor) is added.
# Prints, per load, the tracker's own summary: per-batch latency (mean, p99, max), wall time,
# peak RSS, tracks initiated and initiations refused by the tentative-track capacity.
# Usage: tools/experiments/plot-flood.sh [cloud sizes] [spread sizes]
#   defaults: "250 500 1000 3000" and "10000 100000 240000" (240 000 plots: a line just
#   under the readers' 16 MiB line limit)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
clouds=${1:-250 500 1000 3000}
spreads=${2:-10000 100000 240000}
out="$root/out/experiments/plot-flood"
mkdir -p "$out"

# plots.jsonl for one load: kind (cloud or spread) and size; seeded, so the same every run.
generate() {
  python3 - "$1" "$2" <<'PY'
import math, random, sys
kind, n = sys.argv[1], int(sys.argv[2])
target, flood = random.Random(7), random.Random(11)
for k in range(14):
    plots = [{"id": 0, "range": round(30000 + 1000 * k + target.gauss(0, 30), 1),
              "azimuth": round(2.0 + target.gauss(0, 0.002), 6)}]
    if 4 <= k <= 9:
        for i in range(1, n + 1):
            if kind == "cloud":
                r, a = 50000 + flood.gauss(0, 150), 0.5 + flood.gauss(0, 0.003)
            else:
                r, a = 200e3 * math.sqrt(flood.random()), 2 * math.pi * flood.random()
            plots.append({"id": i, "range": round(r, 1), "azimuth": round(a, 6)})
    line = {"sensor": 1, "scan": k, "time": 4.0 * k,
            "sigma": {"range": 30.0, "azimuth": 0.002}, "plots": plots}
    print(__import__("json").dumps(line, separators=(",", ":")))
PY
}

run() {
  local kind=$1 n=$2
  local plots="$out/${kind}_${n}.plots.jsonl"
  [ -f "$plots" ] || generate "$kind" "$n" >"$plots"
  echo "== $kind of $n plots, scans 4-9 ($(du -m "$plots" | cut -f1) MB of plots)"
  "$skytrack" track --plots "$plots" --out "$out/${kind}_${n}.tracks.jsonl" --quiet 2>&1 |
    sed 's/^/  /'
}

for n in $clouds; do run cloud "$n"; done
for n in $spreads; do run spread "$n"; done
