#!/usr/bin/env bash
# Compares the point tracker's IMM-JPDA association with the GNN baseline on the same plots.
#
# For each (scenario, JPDA profile, GNN profile, cut-off) and each seed: `skytrack simulate`
# the scenario once, run `skytrack track` on those plots with both profiles, score both with
# `skytrack eval --cutoff C --json` against the truth, and print one Markdown table (means
# over the seeds) plus a per-seed table. Builds nothing: the binary is $SKYTRACK (default
# build/tools/skytrack/skytrack under the repository root).
#
# Usage: tools/experiments/compare-point-trackers.sh [--seeds N] [--first-seed S]
#            [--pair SCENARIO:JPDA_PROFILE:GNN_PROFILE:CUTOFF]... [--out DIR]
#   --seeds N       seeds per scenario (default 5): S, S+1, ..., S+N-1
#   --first-seed S  first seed (default 1)
#   --pair ...      replaces the default pairs; SCENARIO is a file or a name under
#                   config/scenarios/, a profile a file, a name under config/profiles/, or
#                   `default` for the built-in default profile (no --profile); CUTOFF [m]
#                   is the OSPA/GOSPA cut-off c (order p = 2)
#   --out DIR       where plots, truth, tracks, logs and scores go
#                   (default out/experiments/compare-point-trackers; out/ is git-ignored)
# Default pairs and cut-offs (c about twice a single plot's 3-D position error at the
# longest target range, so that ordinary localisation error and turn lag are scored as
# localisation and only a track that is really elsewhere counts as missed + false):
#   point_20_targets:default:gnn:1000
#       ground radar, targets to 95 km: sigma 50 m range, 2 mrad (190 m cross-range) and
#       4 mrad (380 m in height) at 95 km, about 430 m in 3-D per plot; c = 1000 m. With
#       c = 500 m most "fragmentations" (117 against 26 over seeds 1-5) are tracks
#       500-800 m off their target for a scan or two (height at 60-90 km, track starts,
#       5 g turns), not lost tracks.
#   airborne_30_targets:airborne:airborne_gnn:2000
#       AEW radar, targets to 133 km: 30 m, 3 mrad (400 m) and 6 mrad (800 m in height) at
#       133 km, about 900 m per plot, 10 s between looks; c = 2000 m.
# Table columns: GOSPA and OSPA means over scans and seeds [m]; GOSPA^2 split into its
# localisation / missed / false parts (% of the mean GOSPA^2 = loc + c^2/2 (missed + false));
# missed truths and false tracks per scan; RMSE over matched pairs; id changes and
# fragmentations per run (mean over seeds); tracker latency per batch p50 / p99 (mean over
# seeds of each run's figure, from `track`'s stderr line); peak RSS (largest run).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
skytrack=${SKYTRACK:-$root/build/tools/skytrack/skytrack}
seeds=5
first_seed=1
out="$root/out/experiments/compare-point-trackers"
pairs=()

usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d' | sed 's/^# \{0,1\}//'; }
while [[ $# -gt 0 ]]; do
  case "$1" in
    --seeds) seeds=$2; shift 2 ;;
    --first-seed) first_seed=$2; shift 2 ;;
    --pair) pairs+=("$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "compare-point-trackers: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
if [[ ${#pairs[@]} -eq 0 ]]; then
  pairs=("point_20_targets:default:gnn:1000" "airborne_30_targets:airborne:airborne_gnn:2000")
fi
[[ "$seeds" =~ ^[1-9][0-9]*$ ]] || { echo "compare-point-trackers: --seeds must be >= 1" >&2; exit 2; }
[[ "$first_seed" =~ ^[0-9]+$ ]] || { echo "compare-point-trackers: bad --first-seed" >&2; exit 2; }
[[ -x "$skytrack" ]] || { echo "compare-point-trackers: no skytrack binary at $skytrack (set SKYTRACK)" >&2; exit 2; }
if ! "$skytrack" --help 2>&1 | grep -Eq '^[[:space:]]+track[[:space:]]'; then
  echo "compare-point-trackers: $skytrack has no 'track' subcommand" >&2; exit 2
fi

scenario_file() {  # name or path -> path
  if [[ -f "$1" ]]; then echo "$1"; elif [[ -f "$root/config/scenarios/$1.yaml" ]]; then
    echo "$root/config/scenarios/$1.yaml"; else echo "no scenario '$1'" >&2; return 1; fi
}
profile_file() {  # name or path -> path; empty for the built-in default
  if [[ "$1" == default ]]; then echo ""; elif [[ -f "$1" ]]; then echo "$1";
  elif [[ -f "$root/config/profiles/$1.yaml" ]]; then echo "$root/config/profiles/$1.yaml";
  else echo "no profile '$1'" >&2; return 1; fi
}

# Fail fast: every scenario and profile exists and every profile file is valid.
for pair in "${pairs[@]}"; do
  IFS=: read -r scen jpda gnn cutoff <<<"$pair"
  [[ -n "${cutoff:-}" ]] || { echo "compare-point-trackers: bad --pair '$pair'" >&2; exit 2; }
  scenario_file "$scen" >/dev/null
  for profile in "$jpda" "$gnn"; do
    profile_path=$(profile_file "$profile")
    [[ -z "$profile_path" ]] || "$skytrack" check-profile "$profile_path" >&2
  done
done

mkdir -p "$out"
manifest="$out/manifest.tsv"
: >"$manifest"
echo "compare-point-trackers: $skytrack, seeds $first_seed..$((first_seed + seeds - 1)), output in $out" >&2

for pair in "${pairs[@]}"; do
  IFS=: read -r scen jpda gnn cutoff <<<"$pair"
  scen_path=$(scenario_file "$scen")
  scen_name=$(basename "$scen_path" .yaml)
  for ((seed = first_seed; seed < first_seed + seeds; ++seed)); do
    base="$out/$scen_name.seed$seed"
    if ! "$skytrack" simulate --scenario "$scen_path" --seed "$seed" --plots "$base.plots.jsonl" \
      --truth "$base.truth.jsonl" >"$base.simulate.log" 2>&1; then
      cat "$base.simulate.log" >&2
      exit 1
    fi
    for assoc in jpda gnn; do
      profile=$jpda
      [[ $assoc == gnn ]] && profile=$gnn
      profile_path=$(profile_file "$profile")
      args=()
      [[ -n "$profile_path" ]] && args=(--profile "$profile_path")
      run="$base.$assoc"
      start=$(date +%s%N)
      if ! "$skytrack" track "${args[@]}" --plots "$base.plots.jsonl" --out "$run.tracks.jsonl" \
        --quiet 2>"$run.track.log"; then
        echo "compare-point-trackers: track failed on $scen_name seed $seed ($assoc, $profile):" >&2
        tail -n 20 "$run.track.log" >&2
        exit 1
      fi
      end=$(date +%s%N)
      wall=$(printf '%d.%03d' $(((end - start) / 1000000000)) $(((end - start) / 1000000 % 1000)))
      "$skytrack" eval --truth "$base.truth.jsonl" --tracks "$run.tracks.jsonl" \
        --cutoff "$cutoff" --json >"$run.eval.json"
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$scen_name" "$assoc" "$profile" "$seed" "$cutoff" \
        "$run" "$wall" >>"$manifest"
      printf '  %-22s seed %-3s %-5s (%s): track %s s\n' "$scen_name" "$seed" "$assoc" "$profile" \
        "$wall" >&2
    done
  done
done

python3 - "$manifest" <<'PY'
import json, math, re, sys
from collections import OrderedDict

UNIT_MS = {"ns": 1e-6, "us": 1e-3, "µs": 1e-3, "ms": 1.0, "s": 1e3}
UNIT_MIB = {"b": 1 / 1048576, "kb": 1 / 1024, "kib": 1 / 1024, "k": 1 / 1024, "mb": 1.0,
            "mib": 1.0, "m": 1.0, "gb": 1024.0, "gib": 1024.0, "g": 1024.0}

def latency(text, key):
    """Milliseconds after `key` (p50, p99, max) on the line that reports per-batch latency."""
    for line in text.splitlines():
        if not re.search(r"p50", line, re.I):
            continue
        m = re.search(key + r"\s*[=:]?\s*([0-9.]+(?:e[-+]?\d+)?)\s*(ns|us|µs|ms|s)?\b", line, re.I)
        if m:
            unit = (m.group(2) or "ms").lower()
            return float(m.group(1)) * UNIT_MS.get(unit, 1.0)
    return math.nan

def peak_rss(text):
    m = re.search(r"rss\s*[=:]?\s*([0-9.]+)\s*([kmg]i?b|[kmg]|b)?\b", text, re.I)
    if not m:
        return math.nan
    return float(m.group(1)) * UNIT_MIB.get((m.group(2) or "kib").lower(), 1 / 1024)

runs = []
for line in open(sys.argv[1]):
    scen, assoc, profile, seed, cutoff, base, wall = line.rstrip("\n").split("\t")
    score = json.load(open(base + ".eval.json"))
    log = open(base + ".track.log", errors="replace").read()
    runs.append(dict(scen=scen, assoc=assoc, profile=profile, seed=int(seed), c=float(cutoff),
                     s=score, p50=latency(log, "p50"), p99=latency(log, "p99"),
                     rss=peak_rss(log), wall=float(wall)))

def mean(xs):
    xs = [x for x in xs if x is not None and not (isinstance(x, float) and math.isnan(x))]
    return sum(xs) / len(xs) if xs else math.nan

def f(x, nd=1):
    return "n/a" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{nd}f}"

groups = OrderedDict()
for r in runs:
    groups.setdefault((r["scen"], r["assoc"], r["profile"]), []).append(r)

print("| scenario | associator (profile) | seeds | GOSPA [m] | GOSPA² split loc / missed / false [%] "
      "| missed / scan | false / scan | OSPA [m] | RMSE pos [m] | RMSE vel [m/s] | id changes "
      "| fragmentations | ms per batch p50 / p99 | peak RSS [MiB] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for (scen, assoc, profile), rs in groups.items():
    c = rs[0]["c"]
    g = lambda k: mean([r["s"].get(k) for r in rs])
    loc, miss, fal = g("gospa_localisation_mean"), g("gospa_missed_mean"), g("gospa_false_mean")
    parts = [loc, c * c / 2 * miss, c * c / 2 * fal]
    total = sum(parts)
    split = " / ".join(f(100 * p / total, 0) for p in parts) if total > 0 else "n/a"
    rss = max([r["rss"] for r in rs if not math.isnan(r["rss"])], default=math.nan)
    print(f"| {scen} (c = {c:g} m) | {assoc.upper()} ({profile}) | {len(rs)} | {f(g('gospa_mean'))} | {split} "
          f"| {f(miss, 2)} | {f(fal, 2)} | {f(g('ospa_mean'))} | {f(g('rmse_position'))} "
          f"| {f(g('rmse_velocity'))} | {f(g('id_changes'))} | {f(g('fragmentations'))} "
          f"| {f(mean([r['p50'] for r in rs]), 2)} / {f(mean([r['p99'] for r in rs]), 2)} | {f(rss, 0)} |")

print()
print("Per seed:")
print()
print("| scenario | seed | associator | GOSPA [m] | missed / scan | false / scan | RMSE pos [m] "
      "| id changes | fragmentations | ms p50 / p99 | track wall [s] |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
order = {scen: i for i, (scen, _, _) in enumerate(groups)}
for r in sorted(runs, key=lambda r: (order[r["scen"]], r["seed"], r["assoc"] != "jpda")):
    s = r["s"]
    print(f"| {r['scen']} | {r['seed']} | {r['assoc'].upper()} | {f(s.get('gospa_mean'))} "
          f"| {f(s.get('gospa_missed_mean'), 2)} | {f(s.get('gospa_false_mean'), 2)} "
          f"| {f(s.get('rmse_position'))} | {s.get('id_changes')} | {s.get('fragmentations')} "
          f"| {f(r['p50'], 2)} / {f(r['p99'], 2)} | {f(r['wall'], 2)} |")
PY
