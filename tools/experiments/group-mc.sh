#!/usr/bin/env bash
# Paper 000 (labeled box-particle PHD group tracking) experiments, Monte Carlo, as Markdown.
#
#   exp1  six groups with births, deaths, a merge and a split (§4.1): LBP-PHD against the
#         k-means baselines BP-PHD and MS-BP-PHD (k-means seeded at random boxes, and with
#         k-means++); mean OSPA (p = 2, c = 500 m) and group count per scan, mean OSPA over
#         the scans with >= 4 groups, group count right, mean run time per run. The SVG of
#         the first run (truth against the LBP-PHD groups) goes to --svg.
#   exp2  two groups, P_d = 0.98 (§4.2): double label against single label, does the group
#         number survive a missed detection of the whole group.
# Builds nothing: the binary is $SKYTRACK_GROUP_MC (default
# build/tools/experiments/group-mc/skytrack-group-mc under the repository root; build it with
# `cmake --build build --target skytrack-group-mc`). Runs one process at a time.
#
# Usage: tools/experiments/group-mc.sh [--runs N] [--first-seed S] [--only exp1|exp2]
#            [--svg FILE]
#   --runs N        Monte Carlo runs per experiment (default 100, the paper's)
#   --first-seed S  seed of the first run (default 1); run i uses S + i
#   --only E        one experiment only
#   --svg FILE      picture of exp1's first run (default out/experiments/group-mc/exp1.svg;
#                   out/ is git-ignored)
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
binary=${SKYTRACK_GROUP_MC:-$root/build/tools/experiments/group-mc/skytrack-group-mc}
runs=100
first_seed=1
only=""
svg="$root/out/experiments/group-mc/exp1.svg"

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --first-seed) first_seed=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --svg) svg=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "unknown option: $1" >&2; usage >&2; exit 2 ;;
  esac
done
if [[ ! -x "$binary" ]]; then
  echo "no $binary: build the skytrack-group-mc target, or set SKYTRACK_GROUP_MC" >&2
  exit 1
fi
mkdir -p "$(dirname "$svg")"

if [[ -z "$only" || "$only" == exp1 ]]; then
  "$binary" exp1 --runs "$runs" --first-seed "$first_seed" --svg "$svg"
  echo
  echo "SVG of run 1: $svg"
  echo
fi
if [[ -z "$only" || "$only" == exp2 ]]; then
  "$binary" exp2 --runs "$runs" --first-seed "$first_seed"
fi
