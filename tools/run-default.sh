#!/usr/bin/env bash
# The README's first command: build, simulate the shipped default scenario, start skytrackd on
# the default profile, replay the scenario into it over DDS (loopback only) at max rate, record
# the tracks, stop the daemon and evaluate the recorded tracks against the truth.
# Environment: SKYTRACK_BUILD_DIR (default build/), SKYTRACK_DOMAIN (DDS domain, default 0).
# --display: also serve the live picture (`skytrack display`, http://127.0.0.1:8080/, or
# SKYTRACK_DISPLAY_LISTEN), replay at 10x real time so the picture moves, and leave the daemon
# and the page up after the evaluation until Ctrl-C.
set -euo pipefail
display=0
if [ "${1:-}" = "--display" ]; then
  display=1
  shift
fi
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh"
build="${SKYTRACK_BUILD_DIR:-$root/build}"
skytrack="$build/tools/skytrack/skytrack"
skytrackd="$build/tools/skytrackd/skytrackd"
out="$root/out"
mkdir -p "$out"
scenario="${1:-$root/config/scenarios/default.yaml}"

daemon_pid="" record_pid="" display_pid=""
cleanup() {
  local rc=$?
  for pid in $record_pid $display_pid $daemon_pid; do kill -KILL "$pid" 2>/dev/null || true; done
  if [ $rc -ne 0 ]; then
    echo "run-default: failed; daemon log: $out/skytrackd.log" >&2
    tail -n 20 "$out/skytrackd.log" >&2 2>/dev/null || true
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

# The shipped daemon configuration, on the chosen domain.
sed -e "s|^  domain: 0|  domain: ${SKYTRACK_DOMAIN:-0}|" \
  -e "s|profile: profiles/default.yaml|profile: $root/config/profiles/default.yaml|" \
  "$root/config/skytrackd.yaml" >"$out/skytrackd.yaml"

"$skytrack" simulate --scenario "$scenario" --plots "$out/default.plots.jsonl" \
  --truth "$out/default.truth.jsonl"
"$skytrackd" --config "$out/skytrackd.yaml" >"$out/skytrackd.log" 2>&1 &
daemon_pid=$!
wait_for "$out/skytrackd.log" "running" 15 "$daemon_pid" || { echo "skytrackd did not start" >&2; exit 1; }
grep -m1 "DDS:" "$out/skytrackd.log"
rate=max
if [ "$display" = 1 ]; then
  listen=${SKYTRACK_DISPLAY_LISTEN:-127.0.0.1:8080}
  "$skytrack" display --config "$out/skytrackd.yaml" --listen "$listen" >"$out/display.log" 2>&1 &
  display_pid=$!
  wait_for "$out/display.log" "serving" 15 "$display_pid" ||
    { cat "$out/display.log" >&2; echo "skytrack display did not start" >&2; exit 1; }
  echo "live picture: http://$listen/ (open it now: the replay starts in 5 s)"
  sleep 5
  rate=10
fi
timeout 120 "$skytrack" record --config "$out/skytrackd.yaml" --tracks "$out/default.tracks.jsonl" \
  --until-idle 2 >"$out/record.log" 2>&1 &
record_pid=$!
wait_for "$out/record.log" "matched a TrackBatch writer" 15 "$record_pid" ||
  { echo "record did not match the daemon" >&2; exit 1; }
timeout 120 "$skytrack" replay --config "$out/skytrackd.yaml" --plots "$out/default.plots.jsonl" --rate "$rate"
wait "$record_pid"
record_pid=""
cat "$out/record.log" | tail -n 1
echo "daemon status:"
"$skytrack" status --config "$out/skytrackd.yaml"
if [ "$display" = 1 ]; then
  "$skytrack" eval --truth "$out/default.truth.jsonl" --tracks "$out/default.tracks.jsonl" \
    --cutoff 500 --plot "$out/default.svg"
  echo "live picture: http://$listen/ ; the daemon and the page stay up: Ctrl-C to stop"
  trap 'kill -TERM $display_pid $daemon_pid 2>/dev/null; wait; display_pid="" daemon_pid=""; exit 0' INT TERM
  wait "$display_pid"
  exit 0
fi
kill -TERM "$daemon_pid"
for _ in $(seq 50); do kill -0 "$daemon_pid" 2>/dev/null || break; sleep 0.1; done
wait "$daemon_pid"
daemon_pid=""
echo "skytrackd stopped"
# Cut-off 500 m: a few times the height error of a 3 mrad elevation at 40-60 km.
"$skytrack" eval --truth "$out/default.truth.jsonl" --tracks "$out/default.tracks.jsonl" \
  --cutoff 500 --plot "$out/default.svg"
echo "picture: $out/default.svg"
