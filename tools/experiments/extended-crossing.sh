#!/usr/bin/env bash
# The shipped multi-object extended scenario (config/scenarios/extended_crossing.yaml: four
# objects, two crossing at the origin, Poisson clutter mean 20 per scan, Gaussian noise
# N(0, U/4); table C of docs/extended.md as a YAML scenario) tracked with
# config/profiles/extended.yaml for each estimator (`extended.estimator`: smf,
# random_matrix, mem_ekf). For each seed: `skytrack simulate` once, `skytrack track` with
# the three profiles, `skytrack eval --cutoff 200 --json` (as docs/extended.md's "Running
# it"); prints one Markdown row per estimator (means over the seeds, number changes and
# fragmentations summed) and the seeds with number changes. Builds nothing: the binary is
# $SKYTRACK (default build/tools/skytrack/skytrack under the repository root).
#
# Usage: tools/experiments/extended-crossing.sh [--seeds N] [--first-seed S] [--out DIR]
#   --seeds N       seeds (default 20): S .. S+N-1
#   --first-seed S  first seed (default 1)
#   --out DIR       profiles, plots, truth, tracks, logs and scores
#                   (default out/experiments/extended-crossing; out/ is git-ignored)
# Columns: position and velocity RMSE and the mean GWD of the extents over matched
# track-truth pairs (eval's rmse_position, rmse_velocity, gwd_mean), number changes (eval's
# id_changes: the track on a truth object changed number, over each scan's GOSPA pairs; and
# kept_id_changes, over CLEAR MOT's kept correspondence, where two objects overlapping in
# the crossing are not a change) and fragmentations summed over the seeds, false tracks per
# scan (eval's gospa_false_mean), ms per scan (`skytrack track`'s "per batch: mean", CPU of
# the whole pipeline).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
seeds=20
first=1
out=$root/out/experiments/extended-crossing
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h | --help) sed -n '2,23p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
[ -x "$skytrack" ] || {
  echo "extended-crossing: no binary at $skytrack (build target skytrack, or set SKYTRACK)" >&2
  exit 2
}
mkdir -p "$out"

scenario=$root/config/scenarios/extended_crossing.yaml
estimators=(smf random_matrix mem_ekf)
json_number() { grep -o "\"$1\": [-0-9.e+]*" "$2" | head -n1 | awk '{print $2}'; }

# One profile per estimator: the shipped profile with `extended.estimator` replaced.
for estimator in "${estimators[@]}"; do
  sed -e "s/^  estimator: smf /  estimator: $estimator /" "$root/config/profiles/extended.yaml" \
    >"$out/$estimator.yaml"
  grep -q "^  estimator: $estimator " "$out/$estimator.yaml" || {
    echo "extended-crossing: could not set extended.estimator in $out/$estimator.yaml" >&2
    exit 1
  }
  : >"$out/$estimator.scores"
done

for seed in $(seq "$first" $((first + seeds - 1))); do
  "$skytrack" simulate --scenario "$scenario" --seed "$seed" \
    --plots "$out/s$seed.plots.jsonl" --truth "$out/s$seed.truth.jsonl" >/dev/null
  for estimator in "${estimators[@]}"; do
    log=$out/s$seed.$estimator.log
    "$skytrack" track --profile "$out/$estimator.yaml" --plots "$out/s$seed.plots.jsonl" \
      --out "$out/s$seed.$estimator.tracks.jsonl" --quiet 2>"$log"
    "$skytrack" eval --truth "$out/s$seed.truth.jsonl" \
      --tracks "$out/s$seed.$estimator.tracks.jsonl" --cutoff 200 --json \
      >"$out/s$seed.$estimator.json"
    ms=$(grep -o 'per batch: mean [0-9.]*' "$log" | awk '{print $4}')
    j=$out/s$seed.$estimator.json
    echo "$seed $(json_number rmse_position "$j") $(json_number rmse_velocity "$j")" \
      "$(json_number gwd_mean "$j") $(json_number id_changes "$j")" \
      "$(json_number fragmentations "$j") $(json_number gospa_false_mean "$j") $ms" \
      "$(json_number kept_id_changes "$j")" \
      >>"$out/$estimator.scores"
  done
done

echo
echo "config/scenarios/extended_crossing.yaml, config/profiles/extended.yaml, seeds $first-$((first + seeds - 1));"
echo "\`skytrack eval --cutoff 200\`: means over the seeds, number changes and fragmentations summed."
echo
echo "| estimator | position RMSE [m] | velocity RMSE [m/s] | GWD [m] | number changes | number changes, kept correspondence | fragmentations | false tracks per scan | ms per scan |"
echo "|---|---|---|---|---|---|---|---|---|"
for estimator in "${estimators[@]}"; do
  awk -v name="$estimator" '
    { p += $2; v += $3; g += $4; c += $5; f += $6; x += $7; ms += $8; kc += $9; k++ }
    END {
      printf "| %s | %.1f | %.2f | %.1f | %d | %d | %d | %.3f | %.3f |\n", name, p / k, v / k, g / k,
        c, kc, f, x / k, ms / k
    }' "$out/$estimator.scores"
done
echo
for estimator in "${estimators[@]}"; do
  changed=$(awk '$5 > 0 { printf "%s%s (%d)", sep, $1, $5; sep = ", " }' "$out/$estimator.scores")
  kept=$(awk '$9 > 0 { printf "%s%s (%d)", sep, $1, $9; sep = ", " }' "$out/$estimator.scores")
  echo "$estimator: seeds with number changes: ${changed:-none}; kept correspondence: ${kept:-none}"
done
