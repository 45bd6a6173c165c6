#!/usr/bin/env bash
# The two-radar fusion deployment on one host (docs/fusion.md, "Deployment"): builds, simulates
# the shipped two-radar scenario, starts one skytrackd tracker per radar and one skytrackd in
# the fusion role (config/two-radars/), replays both radars' plots over DDS (loopback only),
# records the local and the fused tracks, stops the nodes and scores each radar's tracks and
# the fused picture against the truth.
# Environment: SKYTRACK_BUILD_DIR (default build/), SKYTRACK_DOMAIN (DDS domain, default 0).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
build="${SKYTRACK_BUILD_DIR:-$root/build}"
skytrack="$build/tools/skytrack/skytrack"
skytrackd="$build/tools/skytrackd/skytrackd"
out="$root/out/fusion"
mkdir -p "$out"

pids=""
cleanup() {
  local rc=$?
  for pid in $pids; do kill -KILL "$pid" 2>/dev/null || true; done
  if [ $rc -ne 0 ]; then
    echo "run-fusion: failed; logs in $out" >&2
    tail -n 5 "$out"/*.log >&2 2>/dev/null || true
  fi
}
trap cleanup EXIT
# Waits up to $3 seconds for file $1 to contain $2 while process $4 lives.
wait_for() {
  for _ in $(seq $(($3 * 10))); do
    grep -q "$2" "$1" 2>/dev/null && return 0
    kill -0 "$4" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}
stop() {
  kill -TERM "$1"
  for _ in $(seq 50); do kill -0 "$1" 2>/dev/null || break; sleep 0.1; done
  wait "$1"
}

# The shipped node configurations, on the chosen domain, with their paths made absolute.
for node in radar1 radar2 fusion; do
  sed -e "s|\.\./|$root/config/|" "$root/config/two-radars/$node.yaml" >"$out/$node.yaml"
  printf 'dds: {domain: %s, qos: {tracks: {history_depth: 1000}}}\n' "${SKYTRACK_DOMAIN:-0}" \
    >>"$out/$node.yaml"
done
printf 'dds: {domain: %s, topics: {tracks: skytrack_fused}, qos: {tracks: {history_depth: 1000}}}\n' \
  "${SKYTRACK_DOMAIN:-0}" >"$out/fused-recorder.yaml"

for scenario in fusion_two_radars fusion_two_radars_sensor2; do
  "$skytrack" simulate --scenario "$root/config/scenarios/$scenario.yaml" \
    --plots "$out/$scenario.plots.jsonl" --truth "$out/$scenario.truth.jsonl"
done
for node in radar1 radar2 fusion; do
  "$skytrackd" --config "$out/$node.yaml" >"$out/$node.log" 2>&1 &
  pid=$!
  pids="$pids $pid"
  eval "${node}_pid=$pid"
  wait_for "$out/$node.log" "running" 15 "$pid" || { echo "skytrackd $node did not start" >&2; exit 1; }
done
timeout 120 "$skytrack" record --config "$out/radar1.yaml" --tracks "$out/local.tracks.jsonl" \
  --until-idle 2 >"$out/record-local.log" 2>&1 &
local_pid=$!
timeout 120 "$skytrack" record --config "$out/fused-recorder.yaml" \
  --tracks "$out/fused.tracks.jsonl" --until-idle 3 >"$out/record-fused.log" 2>&1 &
fused_pid=$!
pids="$pids $local_pid $fused_pid"
for r in local fused; do
  pid_var="${r}_pid"
  wait_for "$out/record-$r.log" "matched a TrackBatch writer" 15 "${!pid_var}" ||
    { echo "the $r recorder did not match a writer" >&2; exit 1; }
done
# As fast as the trackers answer, one scan in flight (--window 1): their frames reach the
# fusion node in time order across sensors, as they do live.
timeout 120 "$skytrack" replay --config "$out/radar1.yaml" --rate max --window 1 --quiet \
  --plots "$out/fusion_two_radars.plots.jsonl" --plots "$out/fusion_two_radars_sensor2.plots.jsonl"
wait "$local_pid"
stop "$radar1_pid"
stop "$radar2_pid"
stop "$fusion_pid"
wait "$fused_pid"
pids=""
echo "nodes stopped"

# Each radar's own picture (split from the recorded local tracks), then the fused one. Cut-off
# 500 m: a few times these radars' cross-range errors at 40-60 km (2 mrad).
for sensor in 1 2; do
  grep "^{\"sensor\":$sensor," "$out/local.tracks.jsonl" >"$out/radar$sensor.tracks.jsonl"
  echo "radar $sensor alone:"
  "$skytrack" eval --truth "$out/fusion_two_radars.truth.jsonl" \
    --tracks "$out/radar$sensor.tracks.jsonl" --cutoff 500 | head -n 9
done
echo "fused:"
"$skytrack" eval --truth "$out/fusion_two_radars.truth.jsonl" --tracks "$out/fused.tracks.jsonl" \
  --cutoff 500 --plot "$out/fused.svg"
echo "picture: $out/fused.svg"
