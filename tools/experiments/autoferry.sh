#!/usr/bin/env bash
# The maritime check with truth: the Autoferry recordings (a real navigation radar in
# Trondheim harbour, two boats with GNSS truth, real clutter; ../shared/realdata/README.md).
#
# For each of the nine scenarios: `skytrack track` its plots with the profile, score the
# tracks against the two boats with `skytrack eval --cutoff 50 --json`, and print one
# Markdown table, one row per scenario, then the count of scenarios in which neither boat's
# track number changed more than once. Builds nothing: the binary is $SKYTRACK (default
# build/tools/skytrack/skytrack under the repository root).
#
# Usage: tools/experiments/autoferry.sh [--profile P] [--data DIR] [--out DIR]
#   --profile P   a profile file or a name under config/profiles/ (default: maritime;
#                 `default` for the built-in default profile)
#   --data DIR    the recordings (default ../shared/realdata/autoferry beside the repository)
#   --out DIR     tracks and scores (default out/experiments/autoferry; out/ is git-ignored)
# Columns: scans; GOSPA and OSPA means over the scans (c = 50 m, p = 2) [m]; position RMSE
# over matched pairs [m]; number changes of boat 1 / boat 2 (eval's id changes per truth
# object: the first number a boat gets is not a change); missed boats and false tracks per
# scan (confirmed or coasting tracks no boat is matched to), and of those false tracks the
# share that stand still (speed under 1 m/s at the scan: quays, moored boats, buoys; the
# boats under way move at 2-3 m/s).
# The truth lists only the two boats: other objects in the harbour (moored boats, quays,
# other traffic) give tracks that count as false here although they are real.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
profile=maritime
data="$root/../shared/realdata/autoferry"
out="$root/out/experiments/autoferry"

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --profile) profile=$2; shift 2 ;;
    --data) data=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "autoferry: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ -x "$skytrack" ]] || { echo "autoferry: no skytrack binary at $skytrack (set SKYTRACK)" >&2; exit 2; }
[[ -d "$data" ]] || { echo "autoferry: no recordings in $data (see --data)" >&2; exit 2; }
args=()
if [[ "$profile" != default ]]; then
  if [[ -f "$profile" ]]; then path=$profile
  elif [[ -f "$root/config/profiles/$profile.yaml" ]]; then path="$root/config/profiles/$profile.yaml"
  else echo "autoferry: no profile '$profile'" >&2; exit 2; fi
  "$skytrack" check-profile "$path" >&2
  args=(--profile "$path")
fi

mkdir -p "$out"
scenarios=(2 3 4 5 6 13 16 17 22)
for n in "${scenarios[@]}"; do
  plots="$data/scenario$n.plots.jsonl"
  truth="$data/scenario$n.truth.jsonl"
  [[ -f "$plots" && -f "$truth" ]] || { echo "autoferry: scenario $n missing in $data" >&2; exit 2; }
  if ! "$skytrack" track "${args[@]}" --plots "$plots" --out "$out/scenario$n.tracks.jsonl" \
    --quiet 2>"$out/scenario$n.track.log"; then
    echo "autoferry: track failed on scenario $n:" >&2
    tail -n 20 "$out/scenario$n.track.log" >&2
    exit 1
  fi
  "$skytrack" eval --truth "$truth" --tracks "$out/scenario$n.tracks.jsonl" --cutoff 50 --json \
    >"$out/scenario$n.eval.json"
done

python3 - "$out" "$data" "${scenarios[@]}" <<'PY'
import json, math, sys

out, data, scenarios = sys.argv[1], sys.argv[2], sys.argv[3:]
CUTOFF, STILL = 50.0, 1.0

def stationary_false(n):
    """False tracks per scan and their stationary share: firm tracks with no boat within c."""
    truth = {}
    for line in open(f"{data}/scenario{n}.truth.jsonl"):
        frame = json.loads(line)
        truth[round(frame["time"], 3)] = [o["position"][:2] for o in frame["objects"]]
    false = still = scans = 0
    for line in open(f"{out}/scenario{n}.tracks.jsonl"):
        frame = json.loads(line)
        boats = truth.get(round(frame["time"], 3))
        if boats is None:
            continue
        scans += 1
        firm = [t for t in frame["tracks"] if t["status"] in ("confirmed", "coasting")]
        # Tracks eval leaves unmatched: those farther than c from every boat, plus the
        # surplus when more firm tracks than boats lie within c.
        near = [t for t in firm if any(math.dist(t["position"][:2], b) < CUTOFF for b in boats)]
        far = [t for t in firm if t not in near]
        surplus = max(0, len(near) - len(boats))
        false += len(far) + surplus
        still += sum(1 for t in far if math.hypot(*t["velocity"][:2]) < STILL)
    return false / max(scans, 1), still / max(false, 1)

def fmt(x):  # None: no track matched a boat (eval has no pairs to score)
    return "-" if x is None else f"{x:.1f}"

print("| scenario | scans | GOSPA [m] | OSPA [m] | RMSE pos [m] | number changes boat 1 / 2 "
      "| missed boats / scan | false tracks / scan | of which still |")
print("|---|---|---|---|---|---|---|---|---|")
good = 0
for n in scenarios:
    e = json.load(open(f"{out}/scenario{n}.eval.json"))
    changes = {c["truth"]: c["id_changes"] for c in e["continuity"]}
    c1, c2 = changes.get(1, 0), changes.get(2, 0)
    good += c1 <= 1 and c2 <= 1
    per_scan, still = stationary_false(n)
    print(f"| {n} | {e['scans']} | {e['gospa_mean']:.1f} | {e['ospa_mean']:.1f} | "
          f"{fmt(e['rmse_position'])} | {c1} / {c2} | {e['gospa_missed_mean']:.2f} | "
          f"{e['gospa_false_mean']:.2f} | {100 * still:.0f} % |")
print(f"\nScenarios with at most one number change per boat: {good} of {len(scenarios)}")
PY
