#!/usr/bin/env bash
# Does the batching change the tracks? The same plots delivered as whole revolutions, as N
# sectors per revolution and in blocks of a few plots (no coverage: the feed says nothing of
# what each batch looked at), tracked with the same profile.
#
# 1. A rotating radar with clutter (config/scenarios/default.yaml, 4 s revolution, eight
#    aircraft, 20 false plots a revolution), simulated per seed: `skytrack rebatch` delivers
#    its plots in each batching, `skytrack track` tracks them, `skytrack eval --hold` scores
#    each truth time against the latest frame at or before it (sector and block frames are
#    not at the truth times). Columns: GOSPA mean over the seeds and its change from the
#    revolutions; number changes; the seeds whose targets are held by exactly the numbers of
#    the revolution run ("same numbers"); CPU of `skytrack track` (user + system, whole
#    process: reading, tracking, writing every frame) and per hour of data.
# 2. The real canalA recording (48 min of an en-route secondary radar, one batch per
#    revolution), when present: the same batchings scored with `skytrack eval --identity`
#    (breaks per identity segment, purity, coverage) and timed.
# Builds nothing: the binary is $SKYTRACK (default build/tools/skytrack/skytrack).
#
# Usage: tools/experiments/compare-batching.sh [--seeds N] [--first-seed S] [--profile P]
#            [--canala FILE] [--batchings LIST] [--out DIR]
#   --seeds N       simulated seeds (default 4): S, S+1, ..., S+N-1
#   --first-seed S  first seed (default 1)
#   --profile P     a profile file or a name under config/profiles/ (default: built-in default)
#   --canala FILE   the canalA plot stream (default ../shared/realdata/contract/
#                   canalA.plots.jsonl beside the repository; skipped when absent; "none")
#   --batchings L   comma-separated from revolution, sectors:N, block:N (default
#                   revolution,sectors:8,sectors:32,sectors:128,block:16,block:4,block:1)
#   --out DIR       default out/experiments/compare-batching (out/ is git-ignored)
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
seeds=4
first_seed=1
profile=default
canala="$root/../shared/realdata/contract/canalA.plots.jsonl"
batchings="revolution,sectors:8,sectors:32,sectors:128,block:16,block:4,block:1"
out="$root/out/experiments/compare-batching"

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first_seed=$2; shift 2 ;;
    --profile) profile=$2; shift 2 ;;
    --canala) canala=$2; shift 2 ;;
    --batchings) batchings=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare-batching: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ "$seeds" =~ ^[0-9]+$ ]] || { echo "compare-batching: bad --seeds" >&2; exit 2; }
[[ "$first_seed" =~ ^[0-9]+$ ]] || { echo "compare-batching: bad --first-seed" >&2; exit 2; }
[[ -x "$skytrack" ]] || { echo "compare-batching: no skytrack binary at $skytrack (set SKYTRACK)" >&2; exit 2; }
args=()
if [[ "$profile" != default ]]; then
  if [[ -f "$profile" ]]; then args=(--profile "$profile")
  elif [[ -f "$root/config/profiles/$profile.yaml" ]]; then args=(--profile "$root/config/profiles/$profile.yaml")
  else echo "compare-batching: no profile '$profile'" >&2; exit 2; fi
fi
IFS=, read -r -a batching_list <<<"$batchings"
for b in "${batching_list[@]}"; do
  [[ "$b" == revolution || "$b" =~ ^(sectors|block):[1-9][0-9]*$ ]] ||
    { echo "compare-batching: bad batching '$b'" >&2; exit 2; }
done
mkdir -p "$out"
manifest="$out/manifest.tsv"
: >"$manifest"

# deliver INPUT BATCHING OUTPUT: the plots of INPUT in BATCHING.
deliver() {
  case "$2" in
    revolution) cp "$1" "$3" ;;
    sectors:*) "$skytrack" rebatch --plots "$1" --sectors "${2#sectors:}" --out "$3" 2>/dev/null ;;
    block:*) "$skytrack" rebatch --plots "$1" --block "${2#block:}" --out "$3" 2>/dev/null ;;
  esac
}

# track PLOTS TRACKS: tracks and writes the CPU seconds (user + system) to TRACKS.cpu.
track() {
  local TIMEFORMAT='%3U %3S'
  { time "$skytrack" track "${args[@]}" --plots "$1" --out "$2" --quiet 2>"$2.log"; } 2>"$2.time" ||
    { echo "compare-batching: track failed on $1" >&2; tail -n 20 "$2.log" >&2; exit 1; }
  awk '{print $1 + $2}' "$2.time" >"$2.cpu"
}

echo "compare-batching: $skytrack, profile $profile, output in $out" >&2
for ((seed = first_seed; seed < first_seed + seeds; ++seed)); do
  base="$out/sim.seed$seed"
  "$skytrack" simulate --scenario "$root/config/scenarios/default.yaml" --seed "$seed" \
    --plots "$base.plots.jsonl" --truth "$base.truth.jsonl" >/dev/null 2>&1
  for b in "${batching_list[@]}"; do
    run="$base.${b/:/}"
    deliver "$base.plots.jsonl" "$b" "$run.plots.jsonl"
    track "$run.plots.jsonl" "$run.tracks.jsonl"
    "$skytrack" eval --truth "$base.truth.jsonl" --tracks "$run.tracks.jsonl" --cutoff 500 \
      --hold --json >"$run.eval.json"
    printf 'sim\t%s\t%s\t%s\n' "$seed" "$b" "$run" >>"$manifest"
  done
  echo "  seed $seed: done" >&2
done
if [[ "$canala" != none && -f "$canala" ]]; then
  for b in "${batching_list[@]}"; do
    run="$out/canalA.${b/:/}"
    deliver "$canala" "$b" "$run.plots.jsonl"
    track "$run.plots.jsonl" "$run.tracks.jsonl"
    "$skytrack" eval --identity --plots "$run.plots.jsonl" --tracks "$run.tracks.jsonl" \
      --json >"$run.eval.json"
    printf 'canalA\t0\t%s\t%s\n' "$b" "$run" >>"$manifest"
  done
  echo "  canalA: done" >&2
elif [[ "$canala" != none ]]; then
  echo "compare-batching: no canalA plot stream at $canala; skipped" >&2
fi

python3 - "$manifest" <<'PY'
import json, statistics, sys
from collections import OrderedDict

sim, canal = OrderedDict(), OrderedDict()
for line in open(sys.argv[1]):
    kind, seed, batching, run = line.rstrip("\n").split("\t")
    result = json.load(open(run + ".eval.json"))
    cpu = float(open(run + ".tracks.jsonl.cpu").read())
    batches = sum(1 for _ in open(run + ".plots.jsonl"))
    (sim if kind == "sim" else canal).setdefault(batching, []).append(
        (int(seed), result, cpu, batches))

def numbers(result):
    return {c["truth"]: sorted(c["tracks"]) for c in result["continuity"]}

if sim:
    ref = {seed: r for seed, r, _, _ in next(iter(sim.values()))}
    ref_gospa = statistics.mean(r["gospa_mean"] for r in ref.values())
    seconds = 240.0  # the scenario's duration
    print("Simulated rotating radar with clutter (config/scenarios/default.yaml), seeds",
          ", ".join(str(s) for s in ref), "\n")
    print("| batching | batches per run | GOSPA mean [m] | vs first row | number changes | "
          "same numbers | CPU per run [s] | CPU per hour of data [s] |")
    print("|---|---|---|---|---|---|---|---|")
    for batching, runs in sim.items():
        gospa = statistics.mean(r["gospa_mean"] for _, r, _, _ in runs)
        same = sum(numbers(r) == numbers(ref[s]) for s, r, _, _ in runs)
        cpu = statistics.mean(c for _, _, c, _ in runs)
        print(f"| {batching} | {statistics.mean(b for *_, b in runs):.0f} | {gospa:.1f} | "
              f"{100 * (gospa / ref_gospa - 1):+.1f} % | "
              f"{statistics.mean(r['id_changes'] for _, r, _, _ in runs):.2f} | "
              f"{same} of {len(runs)} | {cpu:.3f} | {cpu * 3600 / seconds:.2f} |")
    print()
if canal:
    hours = 47.8 / 60  # the recording's length
    print("canalA (real en-route secondary radar, 48 min), scored by identity\n")
    print("| batching | batches | breaks per segment | purity | coverage | CPU [s] | "
          "CPU per hour of data [s] |")
    print("|---|---|---|---|---|---|---|")
    for batching, [(_, r, cpu, batches)] in canal.items():
        print(f"| {batching} | {batches} | {r['breaks_per_segment']:.4f} | {r['purity']:.4f} | "
              f"{r['coverage']:.4f} | {cpu:.2f} | {cpu / hours:.2f} |")
PY
