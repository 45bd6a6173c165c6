#!/usr/bin/env bash
# Paper 002's experiment (one extended object, Singer-like model, T = 10 s, 160 s, bounded
# noise, lambda = 0.25), 100 Monte Carlo runs, for SMF-EOT, the random-matrix filter and
# MEM-EKF*; the same on Gaussian noise; and the ExtendedTracker with each estimator on four
# objects (two crossing) in clutter. Prints Markdown tables (docs/extended.md has them next
# to the paper's figures). Builds nothing: the binary is $SKYTRACK_EXTENDED_MC (default
# build/tools/experiments/extended-mc/skytrack-extended-mc under the repository root).
#
# Usage: tools/experiments/extended-mc.sh [--runs N] [--seed S] [--multi-runs M]
#            [--mean-plots P]
#   --runs N        Monte Carlo runs of the one-object experiment (default 100)
#   --multi-runs M  runs of the multi-object scenario (default 100)
#   --seed S        first seed (default 1)
#   --mean-plots P  Poisson mean of the object's plots per scan (default 10; not printed in
#                   the paper)
# Two tables for the one-object experiment: the Bayesian filters given R = U (the paper's
# one printed noise matrix; with SMF-EOT also run with the extent step as printed) and
# R = U/4 (the covariance of noise uniform in E(0, U)).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
binary=${SKYTRACK_EXTENDED_MC:-$root/build/tools/experiments/extended-mc/skytrack-extended-mc}
runs=100
multi_runs=100
seed=1
mean_plots=10
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --multi-runs) multi_runs=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --mean-plots) mean_plots=$2; shift 2 ;;
    *) echo "extended-mc: unknown option $1" >&2; exit 2 ;;
  esac
done
[[ -x "$binary" ]] || {
  echo "extended-mc: no binary at $binary (build target skytrack-extended-mc, or set SKYTRACK_EXTENDED_MC)" >&2
  exit 2
}
"$binary" --table single --runs "$runs" --seed "$seed" --mean-plots "$mean_plots" --bayes-noise bound --literal-smf
"$binary" --table single --runs "$runs" --seed "$seed" --mean-plots "$mean_plots" --bayes-noise moment
"$binary" --table multi --runs "$multi_runs" --seed "$seed"
