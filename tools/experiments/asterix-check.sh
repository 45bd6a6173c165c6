#!/usr/bin/env bash
# The ASTERIX figures of docs/asterix.md: import of the three real captures (counts), canalA
# against the independent decoder's plot stream (../shared/realdata/contract), and the tracks
# of both through `skytrack track` (as imported, and re-timed like the contract).
# Usage: tools/experiments/asterix-check.sh [build dir] (needs python3; tshark is checked by
# the test suite: ctest -R RealCaptures).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build}
tool=$build/tools/skytrack/skytrack
data=$root/../shared/realdata
out=${OUT:-$root/out/asterix}
mkdir -p "$out"
for name in canalA_cat001_cat002 bds30_cat048_cat034 croatia_cat034_cat048; do
  echo "== $name"
  "$tool" import-asterix "$data/asterix/$name.pcap" --plots "$out/$name.plots.jsonl" --quiet 2>&1 | tail -n +2
done
echo "== canalA: tracks of the import and of the contract stream"
"$tool" track --plots "$out/canalA_cat001_cat002.plots.jsonl" --out "$out/canalA.tracks.jsonl" --quiet
"$tool" track --plots "$data/contract/canalA.plots.jsonl" --out "$out/contract.tracks.jsonl" --quiet
python3 - "$out" "$data/contract/canalA.plots.jsonl" "$tool" <<'PY'
import json, math, subprocess, sys
out, contract, tool = sys.argv[1:4]
ours = [json.loads(l) for l in open(out + "/canalA_cat001_cat002.plots.jsonl")]
theirs = [json.loads(l) for l in open(contract)]
off = 66431.0  # the contract counts time from 18:27:11
key = lambda p, o: (round((p["time"] - o) * 128), round(p["azimuth"] * 65536 / (2 * math.pi)), round(p["range"] * 128 / 1852))
n = mism = 0; worst = {"time": 0, "range": 0, "azimuth": 0}; attr = 0
for x, y in zip(ours, theirs):
    if len(x["plots"]) != len(y["plots"]): mism += 1; continue
    for p, q in zip(sorted(x["plots"], key=lambda p: key(p, off)), sorted(y["plots"], key=lambda p: key(p, 0))):
        n += 1
        worst["time"] = max(worst["time"], abs(p["time"] - off - q["time"]))
        worst["range"] = max(worst["range"], abs(p["range"] - q["range"]))
        worst["azimuth"] = max(worst["azimuth"], abs(p["azimuth"] - q["azimuth"]))
        attr += any(p.get(k) != q.get(k) for k in ("mode3a", "flight_level", "mode_s"))
print(f"plots: batches {len(ours)} vs {len(theirs)}, batches of other size {mism}, plots compared {n}, "
      f"max |d time| {worst['time']:.2g} s, |d range| {worst['range']:.2g} m, |d azimuth| {worst['azimuth']:.2g} rad, "
      f"plots with other transponder attributes {attr}")
# The same plots re-timed like the contract (batch time = first plot, times from 18:27:11).
with open(out + "/canalA.retimed.plots.jsonl", "w") as f:
    for x, y in zip(ours, theirs):
        x["sensor"] = 1; x["time"] = y["time"]
        for p in x["plots"]: p["time"] -= off
        f.write(json.dumps(x) + "\n")
subprocess.run([tool, "track", "--plots", out + "/canalA.retimed.plots.jsonl", "--out", out + "/retimed.tracks.jsonl", "--quiet"], check=True, stderr=subprocess.DEVNULL)
def compare(a_file, b_file, label):
    a = [json.loads(l) for l in open(a_file)]; b = [json.loads(l) for l in open(b_file)]
    counts = sum(len(x["tracks"]) != len(y["tracks"]) for x, y in zip(a, b))
    events = sum([e["type"] for e in x["events"]] != [e["type"] for e in y["events"]] for x, y in zip(a, b))
    d = sorted(min((math.dist(t["position"], u["position"]) for u in y["tracks"]), default=1e9) for x, y in zip(a, b) for t in x["tracks"])
    conf = lambda fs: sum(t["status"] == "confirmed" for f in fs for t in f["tracks"])
    print(f"tracks ({label}): frames {len(a)} vs {len(b)}, frames with another track count {counts}, with other event types {events}; "
          f"confirmed track-frames {conf(a)} vs {conf(b)}; distance to the nearest contract track: median {d[len(d)//2]:.3g} m, max {d[-1]:.3g} m")
compare(out + "/canalA.tracks.jsonl", out + "/contract.tracks.jsonl", "as imported, batches timed by the north marker")
compare(out + "/retimed.tracks.jsonl", out + "/contract.tracks.jsonl", "re-timed like the contract")
PY
