#!/usr/bin/env bash
# Paper 003's three experiments, Monte Carlo, branch tracking on against off (plain IMM-JPDA).
#
# For each seed and each shipped scenario config/scenarios/paper003_exp{1,2,3}_*.yaml:
# `skytrack simulate` once, `skytrack track` the same plots with the default profile
# (branching on) and with config/profiles/no_branching.yaml (off), `skytrack eval --json`
# both (cut-off 2000 m, about twice a plot's 3-D error at 80 km), and print one Markdown
# table. Runs go two at a time (the machine has two cores). Builds nothing: the binary is
# $SKYTRACK (default build-rel/tools/skytrack/skytrack, a Release build, under the
# repository root).
#
# Usage: tools/experiments/compare-branching.sh [--seeds N] [--first-seed S] [--jobs J]
#            [--profile P] [--only exp1|exp2|exp3] [--scenario-dir D] [--out DIR]
#   --profile P     the branching-on profile (default: the built-in default profile)
#   --seeds N       seeds per scenario (default 100): S, S+1, ..., S+N-1
#   --first-seed S  first seed (default 1)
#   --jobs J        runs at once (default 2)
#   --only E        one experiment only (repeatable): exp1, exp2 or exp3
#   --scenario-dir D  the scenario files (same names) from D instead of config/scenarios,
#                   e.g. a copy of exp. 2 with another clutter-patch density
#   --out DIR       plots, truth, tracks and scores (default out/experiments/compare-branching;
#                   out/ is git-ignored); the JSON Lines files are gzipped once scored
#                   (100 seeds of the three scenarios: 1.2 GB plain, a third of it gzipped);
#                   zcat to read them
# Columns, per target and run (mean over the seeds), from the scan its first firm
# (confirmed or coasting) track is within 2000 m of it (the track "on" it: the one on it in
# the previous scan while that is still firm and within 2000 m, else the nearest; the
# correspondence rule of the CLEAR MOT metrics, Bernardin & Stiefelhagen 2008):
#   number changes   the number on the target changes (a re-initiation is one of them: the
#                    new number is a new track); "without number change" = % of targets,
#                    and % of runs in which no target's number changed
#   scans lost       scans with no firm track on the target (coasting far off, or none)
#   eval id changes / fragmentations   `skytrack eval` over the whole run (start-up included)
#   number survives  exp. 2: the number on the target at t = 100 s (just before its 3
#                    missed scans) is the one at t = 150 s (after the re-detection at
#                    137.5 s) and that track took a plot (association probability > 0.5)
#                    in t = [135, 150] s (a branch's plot in the frame it replaced the
#                    father counts); exp. 3: from t = 90 s (in the U-turn) to t = 150 s
#   survives the area  exp. 2: that number is on the target at t = 180 s, after it left the
#                    clutter area (at 152 s), and its track took a plot (association
#                    probability > 0.5) in t = [155, 180] s: the number came back to the
#                    target later, if not at the re-detection
#   branch won       exp. 3: a branch_promoted event on that number in t = [100, 150] s
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build-rel/tools/skytrack/skytrack}
seeds=100
first_seed=1
jobs=2
only=()
out="$root/out/experiments/compare-branching"
scenario_dir="$root/config/scenarios"

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first_seed=$2; shift 2 ;;
    --jobs) jobs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --profile) on_profile=$2; shift 2 ;;
    --only) only+=("$2"); shift 2 ;;
    --scenario-dir) scenario_dir=$(cd "$2" && pwd); shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare-branching: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ "$seeds" =~ ^[1-9][0-9]*$ ]] || { echo "compare-branching: --seeds must be >= 1" >&2; exit 2; }
[[ "$first_seed" =~ ^[0-9]+$ ]] || { echo "compare-branching: bad --first-seed" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "compare-branching: bad --jobs" >&2; exit 2; }
[[ -x "$skytrack" ]] || { echo "compare-branching: no skytrack binary at $skytrack (set SKYTRACK)" >&2; exit 2; }

scenarios=()
for scen in paper003_exp1_racetrack_figure_eight paper003_exp2_missed_in_clutter paper003_exp3_uturn; do
  [[ ${#only[@]} -eq 0 || " ${only[*]} " == *" ${scen:9:4} "* ]] && scenarios+=("$scen")
done
[[ ${#scenarios[@]} -gt 0 ]] || { echo "compare-branching: --only takes exp1, exp2 or exp3" >&2; exit 2; }
off_profile="$root/config/profiles/no_branching.yaml"
on_profile=${on_profile:-}
[[ -z "$on_profile" ]] || "$skytrack" check-profile "$on_profile" >/dev/null
"$skytrack" check-profile "$off_profile" >/dev/null
mkdir -p "$out"

# One run: simulate, track on and off, evaluate. Arguments: scenario seed.
one_run() {
  local scen=$1 seed=$2
  local base="$out/$scen.$seed"
  "$skytrack" simulate --scenario "$scenario_dir/$scen.yaml" --plots "$base.plots.jsonl" \
    --truth "$base.truth.jsonl" --seed "$seed" >/dev/null 2>"$base.simulate.log"
  "$skytrack" track ${on_profile:+--profile "$on_profile"} --plots "$base.plots.jsonl" \
    --out "$base.on.tracks.jsonl" --quiet 2>"$base.on.track.log"
  "$skytrack" track --profile "$off_profile" --plots "$base.plots.jsonl" \
    --out "$base.off.tracks.jsonl" --quiet 2>"$base.off.track.log"
  for mode in on off; do
    "$skytrack" eval --truth "$base.truth.jsonl" --tracks "$base.$mode.tracks.jsonl" \
      --cutoff 2000 --json >"$base.$mode.eval.json"
  done
  gzip -1 -f "$base.plots.jsonl" "$base.truth.jsonl" "$base.on.tracks.jsonl" "$base.off.tracks.jsonl"
}
export -f one_run
export skytrack root out off_profile on_profile scenario_dir

for scen in "${scenarios[@]}"; do
  for ((s = first_seed; s < first_seed + seeds; ++s)); do echo "$scen $s"; done
done | xargs -P "$jobs" -n 2 bash -c 'one_run "$0" "$1"'

python3 - "$out" "$first_seed" "$seeds" "${scenarios[@]}" <<'PY'
import gzip, json, math, re, sys

out, first, count = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
scenarios = sys.argv[4:]
seeds = range(first, first + count)
FIRM = ("confirmed", "coasting")
GATE = 2000.0  # [m] a firm track this close to a target is "on" it (the eval cut-off)

def lines(path):
    with gzip.open(path + ".gz", "rt") as f:
        return [json.loads(l) for l in f]

def on_target(truth_frame, track_frame, target, previous):
    """Number of the firm track on the target, or None: the previous frame's number while
    its track is firm and within GATE (CLEAR MOT's correspondence rule: a track passing
    nearer does not take the target), else the nearest firm track within GATE."""
    obj = next((o for o in truth_frame["objects"] if o["id"] == target), None)
    if obj is None:
        return None
    best = None
    for t in track_frame["tracks"]:
        if t["status"] not in FIRM:
            continue
        d = math.dist(obj["position"], t["position"])
        if d <= GATE and t["id"] == previous:
            return previous
        if d <= GATE and (best is None or d < best[0]):
            best = (d, t["id"])
    return best and best[1]

def continuity(truth, tracks, target):
    """After the target's first firm track: number changes, and scans without a firm track."""
    numbers = []
    for a, b in zip(truth, tracks):
        numbers.append(on_target(a, b, target, numbers[-1] if numbers else None))
    changes, gaps, current = 0, 0, None
    for n in numbers:
        if n is None:
            gaps += current is not None
        elif current is None:
            current = n
        elif n != current:
            changes += 1
            current = n
    return numbers, changes, gaps

def at(frames, time):
    return min(range(len(frames)), key=lambda i: abs(frames[i]["time"] - time))

def pct(xs):
    return 100.0 * sum(xs) / max(len(xs), 1)

def promoted(frame):
    # {branch number: the father number it took} for the frame's branch_promoted events
    out = {}
    for e in frame["events"]:
        if e["type"] == "branch_promoted":
            m = re.match(r"\w+ (\d+) of ", e["detail"])
            if m:
                out[int(m.group(1))] = e["track"]
    return out

def mean(xs):
    return sum(xs) / max(len(xs), 1)

rows = []
for scen in scenarios:
    for mode in ("on", "off"):
        ids, frags, changes, gaps, clean, runs_clean, survive, won = [], [], [], [], [], [], [], []
        later = []
        for seed in seeds:
            base = f"{out}/{scen}.{seed}"
            score = json.load(open(f"{base}.{mode}.eval.json"))
            for c in score["continuity"]:
                ids.append(c["id_changes"])
                frags.append(c["fragmentations"])
            truth = lines(base + ".truth.jsonl")
            tracks = lines(f"{base}.{mode}.tracks.jsonl")
            targets = sorted({o["id"] for f in truth for o in f["objects"]})
            run_changes = 0
            for target in targets:
                numbers, n_changes, n_gaps = continuity(truth, tracks, target)
                changes.append(n_changes)
                gaps.append(n_gaps)
                clean.append(n_changes == 0)
                run_changes += n_changes
            runs_clean.append(run_changes == 0)
            if "exp2" in scen:  # before the 3 misses and after the re-detection at 137.5 s
                a, b = numbers[at(truth, 100.0)], numbers[at(truth, 150.0)]
                # and back on its target: a plot of weight > 0.5 since then (a track that
                # only coasted on along the target's straight line does not count)
                # (a branch promoted in a frame took its plot under its own number, which
                # the event's detail names: "son S of track F replaces track F: ...")
                def took(since, until):
                    return any((x["track"] == a or promoted(f).get(x["track"]) == a)
                               and x["probability"] > 0.5
                               for f in tracks if since <= f["time"] <= until
                               for x in f["associations"])
                survive.append(a is not None and a == b and took(135.0, 150.0))
                later.append(a is not None and a == numbers[at(truth, 180.0)]
                             and took(155.0, 180.0))
            if "exp3" in scen:  # in the U-turn and after the two-plot scan
                a, b = numbers[at(truth, 90.0)], numbers[at(truth, 150.0)]
                survive.append(a is not None and a == b)
                won.append(any(e["type"] == "branch_promoted" and e["track"] == a
                               and 100.0 <= f["time"] <= 150.0
                               for f in tracks for e in f["events"]))
        rows.append((scen, mode, mean(changes), mean(gaps), pct(clean), pct(runs_clean),
                     mean(ids), mean(frags),
                     pct(survive) if survive else None, pct(later) if later else None,
                     pct(won) if won else None))

print(f"Seeds {first}-{first + count - 1}: {count} runs per scenario and tracker. Per target, "
      f"from its first firm track on (within {GATE:.0f} m):\n")
print("| scenario | branching | number changes / target | scans lost / target | "
      "targets without number change % | runs without number change % | eval id changes / "
      "target | eval fragmentations / target | number survives % | survives the area % | "
      "branch won % |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for scen, mode, ch, gp, cl, rc, ids, fr, sv, la, wn in rows:
    cell = lambda v: "—" if v is None else f"{v:.0f}"
    print(f"| {scen} | {mode} | {ch:.2f} | {gp:.2f} | {cl:.0f} | {rc:.0f} | {ids:.2f} | {fr:.2f} | "
          f"{cell(sv)} | {cell(la)} | {cell(wn)} |")
PY
