#!/usr/bin/env bash
# Soak run: skytrackd fed by `skytrack replay --loop` at N x real time for M minutes, with the
# daemon's resident set size (VmRSS) printed at the start, every minute and at the end, and
# its final TrackerStatus. Usage: tools/experiments/daemon-soak.sh [minutes=10] [rate=10]
# [scenario=config/scenarios/default.yaml]. Loopback DDS only (domain 230).
# SKYTRACK_BIN_DIR may point at a directory holding copies of skytrack and skytrackd.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
minutes=${1:-10}
rate=${2:-10}
scenario=${3:-$root/config/scenarios/default.yaml}
build=${SKYTRACK_BUILD_DIR:-$root/build}
skytrack=${SKYTRACK_BIN_DIR:+$SKYTRACK_BIN_DIR/skytrack}
skytrack=${skytrack:-$build/tools/skytrack/skytrack}
skytrackd=${SKYTRACK_BIN_DIR:+$SKYTRACK_BIN_DIR/skytrackd}
skytrackd=${skytrackd:-$build/tools/skytrackd/skytrackd}
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"
work=$(mktemp -d)
daemon_pid="" replay_pid=""
cleanup() {
  [ -n "$replay_pid" ] && kill "$replay_pid" 2>/dev/null || true
  [ -n "$daemon_pid" ] && kill "$daemon_pid" 2>/dev/null || true
  wait 2>/dev/null || true
}
trap cleanup EXIT
sed -e "s|^  domain: 0|  domain: 230|" -e "s|profiles/default.yaml|$root/config/profiles/default.yaml|" \
  -e "s|level: info|level: warn|" "$root/config/skytrackd.yaml" >"$work/skytrackd.yaml"
"$skytrack" simulate --scenario "$scenario" --plots "$work/soak.plots.jsonl" --truth "$work/soak.truth.jsonl"
"$skytrackd" --config "$work/skytrackd.yaml" 2>"$work/daemon.log" &
daemon_pid=$!
rss() { awk '/VmRSS/ {print $2 " kB"}' "/proc/$daemon_pid/status"; }
"$skytrack" replay --config "$work/skytrackd.yaml" --plots "$work/soak.plots.jsonl" --rate "$rate" \
  --loop --quiet 2>"$work/replay.log" &
replay_pid=$!
sleep 5
echo "soak: $minutes min at ${rate}x real time of $(basename "$scenario")"
echo "RSS start (after 5 s): $(rss)"
for ((m = 1; m <= minutes; m++)); do
  sleep 60
  echo "RSS after $m min: $(rss)"
done
"$skytrack" status --config "$work/skytrackd.yaml"
echo "RSS end: $(rss)"
kill -INT "$replay_pid" && wait "$replay_pid" || true
replay_pid=""
cat "$work/replay.log"
kill -TERM "$daemon_pid"
wait "$daemon_pid" && echo "skytrackd exited 0"
daemon_pid=""
grep -c "" "$work/daemon.log" | sed 's/^/daemon log lines (warn and above): /'
rm -rf "$work"
