#!/usr/bin/env bash
# Slow, stationary and airport-surface targets: config/scenarios/airport_surface.yaml (an
# airport's Mode S radar; parked aircraft 70-80 m apart, taxiing, a landing and a departure
# on one runway, overflights 300 m apart in height) tracked with each profile.
#
# For each seed: `skytrack simulate` once, `skytrack track` the same plots with every
# profile, `skytrack eval --cutoff 50 --json` (c = 50 m: the stands are 70-80 m apart, so a
# track farther than that from its aircraft is nearer another's), and print one Markdown
# table of means over the seeds, then the number changes per aircraft summed over the seeds.
# Builds nothing: the binary is $SKYTRACK (default build/tools/skytrack/skytrack under the
# repository root).
#
# Usage: tools/experiments/airport.sh [--seeds N] [--first-seed S] [--profile P]... [--out DIR]
#   --seeds N       seeds (default 5): S, S+1, ..., S+N-1
#   --first-seed S  first seed (default 1)
#   --profile P     a profile file, a name under config/profiles/, or `default` for the
#                   built-in default (repeatable; default: ground_surveillance and default)
#   --out DIR       default out/experiments/airport (out/ is git-ignored)
# Columns: GOSPA (p = 2) and its missed / false parts per scan; position RMSE over matched
# pairs; number changes and fragmentations per run (eval's, over all aircraft); number
# changes per run of the parked aircraft (1-6), of the taxiing ones (10, 20 until its
# take-off, 30 after its landing: all of 10, 20 and 30 here), and of the overflights (40, 41).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
seeds=5
first_seed=1
profiles=()
out="$root/out/experiments/airport"

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first_seed=$2; shift 2 ;;
    --profile) profiles+=("$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "airport: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ ${#profiles[@]} -gt 0 ]] || profiles=(ground_surveillance default)
[[ "$seeds" =~ ^[1-9][0-9]*$ ]] || { echo "airport: --seeds must be >= 1" >&2; exit 2; }
[[ -x "$skytrack" ]] || { echo "airport: no skytrack binary at $skytrack (set SKYTRACK)" >&2; exit 2; }
scenario="$root/config/scenarios/airport_surface.yaml"

mkdir -p "$out"
manifest="$out/manifest.tsv"
: >"$manifest"
for ((seed = first_seed; seed < first_seed + seeds; ++seed)); do
  base="$out/seed$seed"
  "$skytrack" simulate --scenario "$scenario" --seed "$seed" --plots "$base.plots.jsonl" \
    --truth "$base.truth.jsonl" >"$base.simulate.log" 2>&1 || { cat "$base.simulate.log" >&2; exit 1; }
  for profile in "${profiles[@]}"; do
    args=()
    if [[ "$profile" != default ]]; then
      path=$profile
      [[ -f "$path" ]] || path="$root/config/profiles/$profile.yaml"
      [[ -f "$path" ]] || { echo "airport: no profile '$profile'" >&2; exit 2; }
      args=(--profile "$path")
    fi
    name=$(basename "$profile" .yaml)
    run="$base.$name"
    "$skytrack" track "${args[@]}" --plots "$base.plots.jsonl" --out "$run.tracks.jsonl" \
      --quiet 2>"$run.track.log"
    "$skytrack" eval --truth "$base.truth.jsonl" --tracks "$run.tracks.jsonl" --cutoff 50 \
      --json >"$run.eval.json"
    printf '%s\t%s\t%s\n' "$name" "$seed" "$run.eval.json" >>"$manifest"
  done
done

python3 - "$manifest" <<'PY'
import json, sys
from collections import OrderedDict, defaultdict

runs = OrderedDict()
for line in open(sys.argv[1]):
    name, seed, path = line.rstrip("\n").split("\t")
    runs.setdefault(name, []).append(json.load(open(path)))
groups = {"parked": {1, 2, 3, 4, 5, 6}, "taxiing": {10, 20, 30}, "overflights": {40, 41}}
print("| profile | seeds | GOSPA [m] | missed / scan | false / scan | RMSE pos [m] "
      "| number changes / run | fragmentations / run | changes parked / taxiing / overflights |")
print("|---|---|---|---|---|---|---|---|---|")
per_aircraft = {}
for name, evals in runs.items():
    n = len(evals)
    mean = lambda key: sum(e[key] for e in evals) / n
    by_group = defaultdict(int)
    per = defaultdict(int)
    for e in evals:
        for c in e["continuity"]:
            per[c["truth"]] += c["id_changes"]
            for g, ids in groups.items():
                if c["truth"] in ids:
                    by_group[g] += c["id_changes"]
    per_aircraft[name] = per
    split = " / ".join(f"{by_group[g] / n:.1f}" for g in groups)
    print(f"| {name} | {n} | {mean('gospa_mean'):.1f} | {mean('gospa_missed_mean'):.2f} | "
          f"{mean('gospa_false_mean'):.2f} | {mean('rmse_position'):.1f} | "
          f"{mean('id_changes'):.1f} | {mean('fragmentations'):.1f} | {split} |")
print("\nNumber changes per aircraft, summed over the seeds:\n")
ids = sorted({t for per in per_aircraft.values() for t in per})
print("| profile | " + " | ".join(str(t) for t in ids) + " |")
print("|---|" + "---|" * len(ids))
for name, per in per_aircraft.items():
    print(f"| {name} | " + " | ".join(str(per[t]) for t in ids) + " |")
PY
