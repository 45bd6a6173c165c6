#!/usr/bin/env bash
# skytrack on the open reference tracker's multi-target benchmark (issue 32), next to the
# reference's published figures (Stone Soup: JPDA with exact EHM and GNN, full pipeline).
#
# The benchmark, reproduced with our simulator from its parameters (config/scenarios/
# peer_benchmark.yaml): targets uniform in [-400, 400]^2 m, velocities N(0, 5^2) m/s per axis,
# white-noise acceleration q = 0.5 m^2/s^3, position plots sigma 5 m, Pd 0.9, Poisson clutter
# uniform over [-500, 500]^2 m, 1 s scans, 50 scans, trackers start empty; GOSPA (c = 25 m,
# p = 1, alpha = 2) on the positions of confirmed and coasting tracks every scan. Cells: 5, 20
# and 50 targets x 10 and 50 clutter plots per scan.
# Trackers, each from config/profiles/peer_benchmark.yaml (the benchmark's facts: one CV model
# with accel_sigma sqrt(q), sigma 5 m, Pd 0.9, the cell's clutter density, gate 0.99; all else
# the built-in default): IMM-JPDA with branching (the default), without branching, and GNN.
# For each cell and seed: simulate once, track with the three profiles, `skytrack eval
# --cutoff 25 --order 1 --json`; the table gives means over the seeds. Builds nothing: the
# binary is $SKYTRACK (default build/tools/skytrack/skytrack under the repository root).
#
# Usage: tools/experiments/compare-peer-benchmark.sh [--seeds N] [--first-seed S] [--out DIR]
#   --seeds N       seeds per cell (default 10): S .. S+N-1; each seed draws its own targets
#   --first-seed S  first seed (default 1)
#   --out DIR       plots, truth, tracks and scores (default out/experiments/peer-benchmark)
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
seeds=10
first=1
out=$root/out/experiments/peer-benchmark
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h | --help) sed -n '2,22p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"

# The reference's figures (issue 32): targets clutter | JPDA ms/scan, GOSPA, missed, false |
# GNN ms/scan, GOSPA.
reference() {
  case "$1/$2" in
    5/10) echo "12 26 0.4 0.0 8 26" ;;
    5/50) echo "88 55 0.4 2.3 85 56" ;;
    20/10) echo "31 105 1.6 0.0 20 105" ;;
    20/50) echo "104 138 1.6 2.6 98 143" ;;
    50/10) echo "80 267 4.8 0.1 52 258" ;;
    50/50) echo "159 279 4.0 1.1 140 290" ;;
  esac
}
json_number() { grep -o "\"$1\": [-0-9.e+]*" "$2" | head -n1 | awk '{print $2}'; }

base_profile=$root/config/profiles/peer_benchmark.yaml
rows=()
for targets in 5 20 50; do
  for clutter in 10 50; do
    cell=$out/t${targets}_c${clutter}
    mkdir -p "$cell"
    # The cell's scenario and the three profiles, with the cell's clutter density.
    sed -e "s/^  count: 50$/  count: $targets/" -e "s/^  mean: 50 /  mean: $clutter /" \
      "$root/config/scenarios/peer_benchmark.yaml" >"$cell/scenario.yaml"
    density=$(awk -v c="$clutter" 'BEGIN { printf "%.6g", c / 1.0e6 }')
    sed -e "s/clutter_density: 5.0e-5 /clutter_density: $density /" "$base_profile" \
      >"$cell/branching.yaml"
    sed -e 's/^  branching:$/  branching:\n    enabled: false/' "$cell/branching.yaml" \
      >"$cell/no_branching.yaml"
    sed -e 's/^association:$/association:\n  method: gnn/' "$cell/no_branching.yaml" >"$cell/gnn.yaml"
    for tracker in branching no_branching gnn; do
      : >"$cell/$tracker.scores"
    done
    for seed in $(seq "$first" $((first + seeds - 1))); do
      "$skytrack" simulate --scenario "$cell/scenario.yaml" --seed "$seed" \
        --plots "$cell/s$seed.plots.jsonl" --truth "$cell/s$seed.truth.jsonl" >/dev/null
      for tracker in branching no_branching gnn; do
        log=$cell/s$seed.$tracker.log
        "$skytrack" track --profile "$cell/$tracker.yaml" --plots "$cell/s$seed.plots.jsonl" \
          --out "$cell/s$seed.$tracker.tracks.jsonl" --quiet 2>"$log"
        "$skytrack" eval --truth "$cell/s$seed.truth.jsonl" \
          --tracks "$cell/s$seed.$tracker.tracks.jsonl" --cutoff 25 --order 1 --json \
          >"$cell/s$seed.$tracker.json"
        ms=$(grep -o 'per batch: mean [0-9.]*' "$log" | awk '{print $4}')
        echo "$ms $(json_number gospa_mean "$cell/s$seed.$tracker.json")" \
          "$(json_number gospa_missed_mean "$cell/s$seed.$tracker.json")" \
          "$(json_number gospa_false_mean "$cell/s$seed.$tracker.json")" \
          "$(json_number id_changes "$cell/s$seed.$tracker.json")" >>"$cell/$tracker.scores"
      done
    done
    read -r ref_ms ref_gospa ref_missed ref_false gnn_ms gnn_gospa <<<"$(reference "$targets" "$clutter")"
    row="| $targets / $clutter | $ref_ms / $ref_gospa / $ref_missed / $ref_false | $gnn_ms / $gnn_gospa"
    for tracker in branching no_branching gnn; do
      row+=$(awk -v ref_ms="$ref_ms" -v ref_gospa="$ref_gospa" '
        { ms += $1; g += $2; m += $3; f += $4; n += $5; k++ }
        END {
          printf " | %.3f / %.1f / %.2f / %.2f / %.1f | %.0fx / %+.0f %%", ms / k, g / k, m / k, f / k,
            n / k, ref_ms / (ms / k), 100 * (g / k - ref_gospa) / ref_gospa
        }' "$cell/$tracker.scores")
    done
    rows+=("$row |")
  done
done

echo
echo "Reference benchmark, $seeds seeds per cell (first $first); GOSPA c = 25 m, p = 1, alpha = 2."
echo "Each skytrack column: ms/scan (mean per batch, CPU of \`skytrack track\`) / GOSPA / missed"
echo "/ false tracks per scan / number changes per run; then speed-up over the reference's JPDA"
echo "and GOSPA against the reference's JPDA (negative: better)."
echo
echo "| targets / clutter | reference JPDA ms / GOSPA / missed / false | reference GNN ms / GOSPA | skytrack branching | vs JPDA | skytrack no branching | vs JPDA | skytrack GNN | vs JPDA |"
echo "|---|---|---|---|---|---|---|---|---|"
for row in "${rows[@]}"; do echo "$row"; done
