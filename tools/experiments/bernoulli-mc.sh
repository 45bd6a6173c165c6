#!/usr/bin/env bash
# Paper 001's Monte Carlo experiment (issue 28, deliverables 4 and 5): the MMBPF with
# 300/700/700 and 1000/1000/1000 particles against the IMMBPF baseline with 1000 per model on
# the paper's scenario (range/bearing sensor, P_D 0.98, 20 clutter plots per scan, CV - CT -
# CV - CT - CV over 100 s), printed as Markdown tables, four cases one after the other:
#   1. the paper's: target in every scan, birth velocity prior m_b / Q_b
#   2. the same with the plot-pair birth proposal (no velocity prior)
#   3. a target born late (scan 10) and dying early (after scan 80), velocity prior
#   4. a target born in the first turn (scan 30) and dying after scan 70, plot pairs
# Builds nothing: the binary is $SKYTRACK_BERNOULLI_MC (default
# build/tools/experiments/bernoulli-mc/skytrack-bernoulli-mc under the repository root).
#
# Usage: tools/experiments/bernoulli-mc.sh [--runs N] [--seed S] [--every K]
#                                          [--filter-seed-offset F] [--per-run PREFIX]
#   --runs N   Monte Carlo runs per case (default 50, as the paper)
#   --seed S   first seed (default 1): runs use S, S+1, ..., S+N-1
#   --every K  per-scan rows every K scans (default 5; 1 prints every scan)
#   --filter-seed-offset F  the filters' seed is the run's + F (default 1000003); another F
#              draws the filters' own Monte Carlo noise afresh on the same plots
#   --per-run PREFIX  also write PREFIX.case1.txt .. case4.txt: per run and filter the
#              position / velocity ARMSE and the scans they cover (to pair two builds)
# Columns: ARMSE over the (run, scan) pairs where the target exists and is reported
# (q > 0.5) within 1 km of it; off-target reports = reported while the target exists but
# more than 1 km from it (a false track from clutter, left out of the RMSE); cardinality
# error = mean over runs and scans of |reported - exists|; missed scans = target exists,
# not reported (scan 0 always: births need a previous scan; with plot pairs scan 1 too);
# false-report scans = reported while no target exists; birth / death: the first report on
# the target within 3 scans of its first scan, the first scan without a report within 3
# scans after its last; run time = one 100-scan run, filter construction included, wall
# clock and the thread's CPU time (the machine may be shared). After each case, each MMBPF
# against the IMMBPF run by run: the mean of the per-run ARMSE difference with its standard
# error and 95 % interval, and the pooled ARMSE's relative difference with a bootstrap
# interval over runs.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
binary=${SKYTRACK_BERNOULLI_MC:-$root/build/tools/experiments/bernoulli-mc/skytrack-bernoulli-mc}
runs=50
seed=1
every=5
offset=1000003
per_run=

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --every) every=$2; shift 2 ;;
    --filter-seed-offset) offset=$2; shift 2 ;;
    --per-run) per_run=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "unknown option $1" >&2; usage >&2; exit 2 ;;
  esac
done
if [[ ! -x $binary ]]; then
  echo "no $binary: build the skytrack-bernoulli-mc target first" >&2
  exit 1
fi

common=(--runs "$runs" --seed "$seed" --every "$every" --filter-seed-offset "$offset")
per_case() { [[ -n $per_run ]] && echo --per-run "$per_run.case$1.txt"; true; }
echo "## 1. Paper 001's scenario, birth velocity prior"; echo
"$binary" "${common[@]}" $(per_case 1) --proposal prior
echo; echo "## 2. Paper 001's scenario, plot-pair birth proposal"; echo
"$binary" "${common[@]}" $(per_case 2) --proposal pairs
echo; echo "## 3. Born late (scan 10), dying early (after scan 80), velocity prior"; echo
"$binary" "${common[@]}" $(per_case 3) --proposal prior --birth-scan 10 --death-scan 80
echo; echo "## 4. Born in the first turn (scan 30), dying after scan 70, plot pairs"; echo
"$binary" "${common[@]}" $(per_case 4) --proposal pairs --birth-scan 30 --death-scan 70
