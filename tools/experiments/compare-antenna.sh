#!/usr/bin/env bash
# Rotating against snapshot antenna: does predicting each plot to its own time make the
# rotating antenna's 4 s revolution cost no accuracy?
#
# config/scenarios/default.yaml (rotating, 4 s revolution, plots timed by azimuth) and
# config/scenarios/default_snapshot.yaml (identical targets, radar and clutter; every plot
# of a scan measured at the scan time; the same truth frames at t = 4, 8, ..., 240 s) are
# simulated with the same seed(s), tracked with the same profile, scored against their
# truth with `skytrack eval --cutoff C --json`, and printed as one Markdown table: one row
# per antenna with the means over the seeds, then one row per seed. Builds nothing: the
# binary is $SKYTRACK (default build/tools/skytrack/skytrack under the repository root).
#
# Usage: tools/experiments/compare-antenna.sh [--seeds N] [--first-seed S] [--profile P]
#            [--cutoff C] [--heading H] [--out DIR]
#   --seeds N       seeds (default 3): S, S+1, ..., S+N-1
#   --first-seed S  first seed (default 1)
#   --profile P     a profile file or a name under config/profiles/ (default: the built-in
#                   default profile, no --profile)
#   --cutoff C      OSPA/GOSPA cut-off [m] (default 500: the radar reaches 80 km with 2 mrad,
#                   160 m cross-range per plot there; a track 500 m off is not that target's)
#   --heading H     radar heading [rad] (platform attitude), default 0: the sweep starts at
#                   this azimuth, so it sets how old each target's plot is at the batch time
#                   (both scenarios get it; the snapshot's plots do not depend on it)
#   --out DIR       default out/experiments/compare-antenna (out/ is git-ignored)
# The same seed does not give the same noise in both (the draws differ), so compare the
# means, not single seeds. The rows are scored at the batch times, so they do not match:
# a rotating batch's tracks are reported at the sweep's end, i.e. extrapolated 0-4 s past
# their last plot (the age set by each target's azimuth against the sweep start, hence
# --heading), and that extrapolation is the whole difference. The estimates at the plot
# times themselves match the snapshot's; tests/tracking/rotating_antenna_test.cpp pins both
# (docs/point-tracker.md, "Rotating antenna against snapshot").
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
seeds=3
first_seed=1
profile=default
cutoff=500
heading=0
out="$root/out/experiments/compare-antenna"

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first_seed=$2; shift 2 ;;
    --profile) profile=$2; shift 2 ;;
    --cutoff) cutoff=$2; shift 2 ;;
    --heading) heading=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare-antenna: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ "$seeds" =~ ^[1-9][0-9]*$ ]] || { echo "compare-antenna: --seeds must be >= 1" >&2; exit 2; }
[[ "$first_seed" =~ ^[0-9]+$ ]] || { echo "compare-antenna: bad --first-seed" >&2; exit 2; }
[[ "$heading" =~ ^-?[0-9]+(\.[0-9]+)?$ ]] || { echo "compare-antenna: bad --heading" >&2; exit 2; }
[[ -x "$skytrack" ]] || { echo "compare-antenna: no skytrack binary at $skytrack (set SKYTRACK)" >&2; exit 2; }
if ! "$skytrack" --help 2>&1 | grep -Eq '^[[:space:]]+track[[:space:]]'; then
  echo "compare-antenna: $skytrack has no 'track' subcommand" >&2; exit 2
fi
args=()
if [[ "$profile" != default ]]; then
  if [[ -f "$profile" ]]; then args=(--profile "$profile")
  elif [[ -f "$root/config/profiles/$profile.yaml" ]]; then args=(--profile "$root/config/profiles/$profile.yaml")
  else echo "compare-antenna: no profile '$profile'" >&2; exit 2; fi
  "$skytrack" check-profile "${args[1]}" >&2
fi

mkdir -p "$out"
# The scenarios, with the radar heading written into their platform block.
declare -A scenarios
for antenna in rotating snapshot; do
  source_file="$root/config/scenarios/default.yaml"
  [[ $antenna == snapshot ]] && source_file="$root/config/scenarios/default_snapshot.yaml"
  scenarios[$antenna]=$source_file
  if [[ "$heading" != 0 ]]; then
    scenarios[$antenna]="$out/$antenna.scenario.yaml"
    sed "/^platform:/,/^\$/ s/^\(  position: .*\)\$/\1\n  attitude: [$heading, 0, 0]/" \
      "$source_file" >"${scenarios[$antenna]}"
    grep -q "^  attitude: \[$heading, 0, 0\]" "${scenarios[$antenna]}" ||
      { echo "compare-antenna: could not set the heading in $source_file" >&2; exit 1; }
  fi
done
manifest="$out/manifest.tsv"
: >"$manifest"
echo "compare-antenna: $skytrack, profile $profile, seeds $first_seed..$((first_seed + seeds - 1)), c = $cutoff m, heading $heading rad, output in $out" >&2
for ((seed = first_seed; seed < first_seed + seeds; ++seed)); do
  for antenna in rotating snapshot; do
    scenario=${scenarios[$antenna]}
    base="$out/$antenna.seed$seed"
    if ! "$skytrack" simulate --scenario "$scenario" --seed "$seed" --plots "$base.plots.jsonl" \
      --truth "$base.truth.jsonl" >"$base.simulate.log" 2>&1; then
      cat "$base.simulate.log" >&2
      exit 1
    fi
    if ! "$skytrack" track "${args[@]}" --plots "$base.plots.jsonl" --out "$base.tracks.jsonl" \
      --quiet 2>"$base.track.log"; then
      echo "compare-antenna: track failed on $antenna seed $seed:" >&2
      tail -n 20 "$base.track.log" >&2
      exit 1
    fi
    "$skytrack" eval --truth "$base.truth.jsonl" --tracks "$base.tracks.jsonl" \
      --cutoff "$cutoff" --json >"$base.eval.json"
    printf '%s\t%s\t%s\n' "$antenna" "$seed" "$base" >>"$manifest"
    echo "  seed $seed $antenna: done" >&2
  done
done

python3 - "$manifest" "$cutoff" "$heading" <<'PY'
import json, math, statistics, sys
from collections import OrderedDict

runs = OrderedDict()
for line in open(sys.argv[1]):
    antenna, seed, base = line.rstrip("\n").split("\t")
    runs.setdefault(antenna, []).append((int(seed), json.load(open(base + ".eval.json"))))

KEYS = [("gospa_mean", "GOSPA [m]", 1), ("gospa_missed_mean", "missed / scan", 2),
        ("gospa_false_mean", "false / scan", 2), ("ospa_mean", "OSPA [m]", 1),
        ("rmse_position", "RMSE pos [m]", 1), ("rmse_velocity", "RMSE vel [m/s]", 2),
        ("id_changes", "id changes", 1), ("fragmentations", "fragmentations", 1)]

def f(x, nd):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{nd}f}"

def mean_sd(xs, nd):
    xs = [x for x in xs if x is not None and not (isinstance(x, float) and math.isnan(x))]
    if not xs:
        return "n/a"
    m = sum(xs) / len(xs)
    return f(m, nd) + (f" ± {statistics.stdev(xs):.{nd}f}" if len(xs) > 1 else "")

print(f"Rotating (default.yaml, 4 s revolution, plots timed by azimuth) against snapshot "
      f"(default_snapshot.yaml); c = {float(sys.argv[2]):g} m, p = 2; radar heading "
      f"{float(sys.argv[3]):g} rad; mean ± sd over seeds.")
print()
print("| antenna | seed | " + " | ".join(k[1] for k in KEYS) + " |")
print("|---|---|" + "---|" * len(KEYS))
for antenna, rs in runs.items():
    cells = [mean_sd([s.get(k) for _, s in rs], nd) for k, _, nd in KEYS]
    print(f"| **{antenna}** | mean of {len(rs)} | " + " | ".join(cells) + " |")
for antenna, rs in runs.items():
    for seed, s in rs:
        cells = [f(s.get(k), nd if k not in ("id_changes", "fragmentations") else 0)
                 for k, _, nd in KEYS]
        print(f"| {antenna} | {seed} | " + " | ".join(cells) + " |")
PY
