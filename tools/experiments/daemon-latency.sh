#!/usr/bin/env bash
# Daemon latency: PlotBatch -> TrackBatch round trip through skytrackd (skytrack bench-latency)
# for 10, 100 and 1000 targets per scan, each with a fresh daemon, next to Cyclone's own
# ddsperf ping/pong round trip for the same payload size as the floor, and the same scans
# tracked offline (bench-latency --write-plots, then skytrack track: the tracking alone).
# Loopback only: every process, ddsperf included, runs with config/dds/loopback.xml
# (domain 231).
# With a period, each scan goes out period_ms after the one before, as a radar sends them,
# instead of as soon as the previous one is answered.
# Usage: tools/experiments/daemon-latency.sh [scans=300] [period_ms=0]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
scans=${1:-300}
period=${2:-0}
build=${SKYTRACK_BUILD_DIR:-$root/build}
skytrack="$build/tools/skytrack/skytrack"
skytrackd="$build/tools/skytrackd/skytrackd"
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"
domain=231
work=$(mktemp -d)
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; rm -rf "$work"; }
trap cleanup EXIT
sed -e "s|^  domain: 0|  domain: $domain|" -e "s|profiles/default.yaml|$root/config/profiles/default.yaml|" \
  -e "s|level: info|level: warn|" "$root/config/skytrackd.yaml" >"$work/skytrackd.yaml"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
echo "round trip PlotBatch -> skytrackd -> TrackBatch, a scan every ${period} ms (0: back to back); floor: ddsperf ping/pong (doubled one-way) at the same size"
for targets in 10 100 1000; do
  n=$scans
  [ "$targets" -ge 1000 ] && n=$((scans / 3))
  "$skytrackd" --config "$work/skytrackd.yaml" 2>"$work/daemon.log" &
  pids=($!)
  line=$("$skytrack" bench-latency --config "$work/skytrackd.yaml" --targets "$targets" --scans "$n" --period-ms "$period")
  echo "$line"
  sleep 1.2  # the next periodic status covers every timed scan
  "$skytrack" status --config "$work/skytrackd.yaml" |
    sed -E 's/.*"latency": \{"p50": ([^,]*), "p99": ([^,]*), "max": ([^}]*)\}.*/    daemon reception->publication (status): p50 \1 s, p99 \2 s, max \3 s/'
  kill -TERM "${pids[0]}"
  wait "${pids[0]}"
  pids=()
  "$skytrack" bench-latency --targets "$targets" --scans "$n" --write-plots "$work/load.plots.jsonl"
  "$skytrack" track --profile "$root/config/profiles/default.yaml" \
    --plots "$work/load.plots.jsonl" --out /dev/null --quiet 2>&1 |
    sed -nE 's/.*per batch: mean ([^,]*), p50 ([^,]*), p99 ([^,]*),.*/    the same scans offline, back to back (skytrack track, warm-up included): per batch p50 \2, p99 \3, mean \1/p'
  size=$(echo "$line" | sed -E 's/.*payload ~ *([0-9]+) B.*/\1/')
  ddsperf -D 7 -i $domain pong waitset >"$work/pong.log" 2>&1 &
  pids=($!)
  # Paced, the floor is paced alike: ddsperf pings at the scans' rate.
  rate=""
  [ "$period" != 0 ] && rate=$(awk -v p="$period" 'BEGIN { printf "%gHz", 1000 / p }')
  ddsperf -D 5 -i $domain ping $rate size "$size" waitset >"$work/ping.log" 2>&1 || true
  wait "${pids[0]}" 2>/dev/null || true
  pids=()
  # ddsperf prints one-way (half round trip) figures each second; take the last full second.
  grep " size $size mean" "$work/ping.log" | tail -n 1 |
    awk -v s="$size" '{for (i = 1; i <= NF; i++) { if ($i == "50%") p50 = $(i+1); if ($i == "99%") p99 = $(i+1) }
      gsub("us", "", p50); gsub("us", "", p99);
      printf "    ddsperf floor %d B: round trip p50 %.1f us  p99 %.1f us\n", s, 2 * p50, 2 * p99 }'
done
