#!/usr/bin/env bash
# The display under load (docs/display.md): N point targets and C clutter plots per scan at one
# scan a second (snapshot 3-D radar, 150 km, Pd 0.9) replayed in real time into skytrackd, once
# without and once with `skytrack display` and a headless Chromium showing its page. Prints the
# daemon's latency p50/p99 (TrackerStatus) for both, and for the second the page's frame rate,
# its slowest draw, the scans it showed and missed, and the size of one frame document.
# Loopback only (config/dds/loopback.xml, domain 232, 127.0.0.1; Chromium resolves no host).
# Usage: tools/experiments/display-load.sh [targets=1000] [clutter=4100] [seconds=60]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
targets=${1:-1000}
clutter=${2:-4100}
seconds=${3:-60}
build=${SKYTRACK_BUILD_DIR:-$root/build}
skytrack="$build/tools/skytrack/skytrack"
skytrackd="$build/tools/skytrackd/skytrackd"
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"
out="$root/out/experiments/display-load"
mkdir -p "$out"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done; wait 2>/dev/null || true; }
trap cleanup EXIT

python3 "$root/tools/experiments/load-scenario.py" display_load "$targets" "$clutter" "$seconds" 1.0 \
  >"$out/scenario.new.yaml"
# The same scenario as last time: its plots are reused.
if ! cmp -s "$out/scenario.new.yaml" "$out/scenario.yaml" || [ ! -s "$out/load.plots.jsonl" ]; then
  mv "$out/scenario.new.yaml" "$out/scenario.yaml"
  "$skytrack" simulate --scenario "$out/scenario.yaml" --plots "$out/load.plots.jsonl" \
    --truth "$out/load.truth.jsonl"
fi
# Domain 232 and a partition of this run's own: nothing else's samples count.
sed -e "s|^  domain: 0|  domain: 232|" -e "s|^  partition: \[\]|  partition: display_load_$$|" -e "s|profiles/default.yaml|$root/config/profiles/default.yaml|" \
  -e "s|level: info|level: warn|" "$root/config/skytrackd.yaml" >"$out/skytrackd.yaml"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"

# One real-time replay; $1 = 1 runs the display and a headless Chromium beside the daemon.
run() {
  local with_display=$1 port=""
  pids=()
  "$skytrackd" --config "$out/skytrackd.yaml" 2>"$out/daemon.log" &
  pids+=($!)
  sleep 1
  if [ "$with_display" = 1 ]; then
    "$skytrack" display --config "$out/skytrackd.yaml" --listen 127.0.0.1:0 2>"$out/display.log" &
    pids+=($!)
    for _ in $(seq 100); do grep -q "serving" "$out/display.log" && break; sleep 0.1; done
    port=$(grep -o '127\.0\.0\.1:[0-9]*' "$out/display.log" | head -1 | cut -d: -f2)
    rm -rf "$out/chromium-profile"
    chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking \
      --disable-component-update --disable-sync --disable-extensions --no-pings \
      "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1" \
      --user-data-dir="$out/chromium-profile" --window-size=1280,800 \
      "http://127.0.0.1:$port/?report=1" >"$out/chromium.log" 2>&1 &
    pids+=($!)
    sleep 3
  fi
  "$skytrack" replay --config "$out/skytrackd.yaml" --plots "$out/load.plots.jsonl" --rate 1 --quiet
  sleep 2.5  # the page's last report and the daemon's last status cover every scan
  local status
  status=$("$skytrack" status --config "$out/skytrackd.yaml")
  python3 - "$status" <<'PY'
import json, sys
s = json.loads(sys.argv[1]); l = s["latency"]
print("  daemon: %d scans, dropped %d, latency p50 %.1f ms, p99 %.1f ms, max %.1f ms; tracks %s"
      % (s["scans_processed"], s["scans_dropped"], l["p50"] * 1e3, l["p99"] * 1e3, l["max"] * 1e3,
         s["tracks"]))
PY
  if [ "$with_display" = 1 ]; then
    local bytes state
    bytes=$(curl -s "http://127.0.0.1:$port/api/frame" | wc -c)
    state=$(curl -s "http://127.0.0.1:$port/api/page-state")
    python3 - "$state" "$bytes" <<'PY'
import json, sys
p = json.loads(sys.argv[1])
s = {"confirmed": [], "tentative": 0, "plots": 0}
for one in p["sensors"].values():  # every sensor the page shows
    s["confirmed"] += one["confirmed"]; s["tentative"] += one["tentative"]; s["plots"] += one["plots"]
print("  page: %s frames/s (requestAnimationFrame), slowest draw %s ms, last %s ms; %d scans shown,"
      " %d missed; last frame %d confirmed, %d tentative, %d plots drawn (%d sensors); frame document %.0f kB"
      % (p["fps"], p["draw_ms_max"], p["draw_ms"], p["scans"], p["scans_missed"],
         len(s["confirmed"]), s["tentative"], s["plots"], len(p["sensors"]),
         int(sys.argv[2]) / 1e3))
PY
    echo "  display CPU: $(ps -o time= -p "${pids[1]}"), chromium (browser process): $(ps -o time= -p "${pids[2]}")"
  fi
  cleanup
}
echo "$targets targets, $clutter clutter plots a scan, 1 scan/s, $seconds s"
echo "without the display:"
run 0
echo "with the display and a headless Chromium on its page:"
run 1
