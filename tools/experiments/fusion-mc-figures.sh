#!/usr/bin/env bash
# The figures of docs/fusion.md: per scan, the share of runs with the right association for
# the adaptive and the fixed blend, one SVG per case and label setting, drawn from
# fusion-mc.sh's per-scan tables (same runs and seeds as its defaults).
#
# Usage: tools/experiments/fusion-mc-figures.sh [--runs N] [--out DIR]
#   --runs N   Monte Carlo runs per case (default 1000, seeds 1001..)
#   --out DIR  where the SVG files go (default docs/figures)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=1000
out=$root/docs/figures
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h | --help) sed -n '2,9p' "$0"; exit 0 ;;
    *) echo "unknown argument: $1" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
for case in merge split; do
  "$root/tools/experiments/fusion-mc.sh" --runs "$runs" --only "$case" |
    awk -v out="$out" -v case_name="$case" '
      /^## Shipped label/ { setting = "hysteresis"; title = "shipped label hysteresis (alpha = 2 pair sigmas)" }
      /^## No label/ { setting = "no-hysteresis"; title = "no label hysteresis (alpha = 0, the paper)" }
      /^\| [0-9]+ \|/ {
        gsub(/ /, ""); split($0, f, "|")
        n[setting]++; t[setting, n[setting]] = f[2]; a[setting, n[setting]] = f[3]; x[setting, n[setting]] = f[4]
        titles[setting] = title
      }
      END {
        for (s in n) {
          file = out "/fusion-" case_name "-" s ".svg"
          W = 640; H = 300; L = 60; R = 20; T = 40; B = 40
          # The y axis from the lowest share, down to a tenth, at most 80 %.
          tmax = t[s, n[s]]; ymin = 0.80
          for (i = 1; i <= n[s]; i++) {
            if (a[s, i] < ymin) ymin = a[s, i]
            if (x[s, i] < ymin) ymin = x[s, i]
          }
          ymin = int(ymin * 10) / 10
          printf "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" font-family=\"sans-serif\" font-size=\"12\">\n", W, H > file
          printf "<rect width=\"%d\" height=\"%d\" fill=\"white\"/>\n", W, H > file
          printf "<text x=\"%d\" y=\"20\">Case %s, %s: runs with the right association</text>\n", L, case_name, titles[s] > file
          for (k = 0; k <= 4; k++) {
            y = ymin + k * (1 - ymin) / 4; py = H - B - (y - ymin) / (1 - ymin) * (H - T - B)
            printf "<line x1=\"%d\" y1=\"%.1f\" x2=\"%d\" y2=\"%.1f\" stroke=\"#ddd\"/><text x=\"%d\" y=\"%.1f\" text-anchor=\"end\">%.0f %%</text>\n", L, py, W - R, py, L - 5, py + 4, 100 * y > file
          }
          for (k = 0; k <= tmax; k += 10) {
            px = L + k / tmax * (W - L - R)
            printf "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%d s</text>\n", px, H - B + 15, k > file
          }
          px = L + 20 / tmax * (W - L - R)
          printf "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#999\" stroke-dasharray=\"4 3\"/><text x=\"%.1f\" y=\"%d\">%s at 20 s</text>\n", px, T, px, H - B, px + 4, T + 12, case_name > file
          for (which = 0; which < 2; which++) {
            printf "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"2\" points=\"", which ? "#d62728" : "#1f77b4" > file
            for (i = 1; i <= n[s]; i++) {
              v = which ? x[s, i] : a[s, i]
              printf "%.1f,%.1f ", L + t[s, i] / tmax * (W - L - R), H - B - (v - ymin) / (1 - ymin) * (H - T - B) > file
            }
            printf "\"/>\n" > file
          }
          printf "<text x=\"%d\" y=\"%d\" fill=\"#1f77b4\">adaptive blend</text><text x=\"%d\" y=\"%d\" fill=\"#d62728\">fixed 0.8 / 0.2</text>\n", W - 250, H - 8, W - 130, H - 8 > file
          printf "</svg>\n" > file
          close(file)
          print file
        }
      }'
done
