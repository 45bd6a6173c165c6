#!/usr/bin/env bash
# Adversarial load (issue 30): skytrackd on a private loopback DDS domain with a configuration
# derived from config/skytrackd.yaml, fed by skytrack-adversary: a good sensor (1) replayed at
# its pace throughout while a second sensor sends plot clouds of growing size, bursts of
# batches, batches just under and over max_plots_per_scan, malformed samples and three batches
# that hijack its clock. Prints the adversary's report (per phase: sensor 1's latency, the
# daemon's rejections by reason, drops, queue depth, VmRSS/VmHWM; at the end sensor 1's frames
# against an offline run of sensor 1 alone), then stops the daemon and says how it exited.
# Builds nothing: the binaries come from build/ (SKYTRACK_BUILD_DIR) or SKYTRACK_BIN_DIR.
#
# Usage: tools/experiments/adversarial-load.sh [skytrack-adversary options...]
#   (skytrack-adversary --help lists them; the defaults run about two minutes)
# Environment:
#   ADVERSARY_DOMAIN     private DDS domain (default 119); never 0
#   ADVERSARY_MAX_PLOTS  the daemon's max_plots_per_scan (default: config/skytrackd.yaml's)
#   ADVERSARY_PROFILE    the daemon's profile (default: config/profiles/default.yaml)
# Loopback only: CYCLONEDDS_URI is set to config/dds/loopback.xml for both processes.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${SKYTRACK_BUILD_DIR:-$root/build}
skytrackd=${SKYTRACK_BIN_DIR:+$SKYTRACK_BIN_DIR/skytrackd}
skytrackd=${skytrackd:-$build/tools/skytrackd/skytrackd}
adversary=${SKYTRACK_BIN_DIR:+$SKYTRACK_BIN_DIR/skytrack-adversary}
adversary=${adversary:-$build/tools/experiments/adversary/skytrack-adversary}
domain=${ADVERSARY_DOMAIN:-119}
profile=${ADVERSARY_PROFILE:-$root/config/profiles/default.yaml}
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"

for binary in "$skytrackd" "$adversary"; do
  if [ ! -x "$binary" ]; then
    echo "adversarial-load: $binary not found: build first (cmake --build build)" >&2
    exit 2
  fi
done
if [ "$domain" = 0 ]; then
  echo "adversarial-load: ADVERSARY_DOMAIN must be a private domain, not 0" >&2
  exit 2
fi

work=$(mktemp -d)
daemon_pid=""
cleanup() {
  if [ -n "$daemon_pid" ] && kill -0 "$daemon_pid" 2>/dev/null; then
    kill -KILL "$daemon_pid" 2>/dev/null || true
    wait "$daemon_pid" 2>/dev/null || true
  fi
  rm -rf "$work"
}
trap cleanup EXIT

config=$work/skytrackd.yaml
sed -e "s|^  domain: 0|  domain: $domain|" \
  -e "s|profile: profiles/default.yaml|profile: $profile|" \
  -e "s|level: info|level: warn|" \
  -e "s|status_period: 1.0|status_period: 0.5|" \
  -e "s|history_depth: 1         # batches kept|history_depth: 1000      # batches kept|" \
  ${ADVERSARY_MAX_PLOTS:+-e "s|max_plots_per_scan: 100000|max_plots_per_scan: $ADVERSARY_MAX_PLOTS|"} \
  "$root/config/skytrackd.yaml" >"$config"
# Every TrackBatch kept for a late joiner: under load the adversary's reader may match the
# daemon's writer only after its first frames, which it must still compare.
if ! grep -q "^  domain: $domain\$" "$config" || ! grep -q "history_depth: 1000 " "$config"; then
  echo "adversarial-load: could not set the domain or the TrackBatch history in the derived configuration" >&2
  exit 2
fi

"$skytrackd" --config "$config" 2>"$work/daemon.log" &
daemon_pid=$!
echo "adversarial-load: skytrackd pid $daemon_pid on domain $domain (config/skytrackd.yaml" \
  "with status_period 0.5, log level warn${ADVERSARY_MAX_PLOTS:+, max_plots_per_scan $ADVERSARY_MAX_PLOTS})" >&2

adversary_status=0
"$adversary" --config "$config" --daemon-pid "$daemon_pid" "$@" || adversary_status=$?

daemon_status=0
if kill -0 "$daemon_pid" 2>/dev/null; then
  kill -TERM "$daemon_pid"
  for _ in $(seq 100); do
    kill -0 "$daemon_pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$daemon_pid" 2>/dev/null; then
    echo "skytrackd did not stop within 10 s of SIGTERM: killed"
    kill -KILL "$daemon_pid"
  fi
  wait "$daemon_pid" || daemon_status=$?
  echo "skytrackd exited $daemon_status after SIGTERM"
else
  wait "$daemon_pid" || daemon_status=$?
  echo "skytrackd had already exited ($daemon_status) before the end of the run"
  daemon_status=1
fi
daemon_pid=""
lines=$(grep -c "" "$work/daemon.log" || true)
echo "skytrackd log (warn and above): $lines lines; the first 12:"
head -n 12 "$work/daemon.log" | cut -c1-240 | sed 's/^/  /'
if [ "$adversary_status" -ne 0 ]; then exit "$adversary_status"; fi
exit "$daemon_status"
