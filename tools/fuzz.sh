#!/usr/bin/env bash
# Runs one libFuzzer target of fuzz/ for N minutes (docs/hardening.md): builds it with clang
# (-DSKYTRACK_FUZZ=ON, in build-fuzz/), copies its committed seeds into a fresh work corpus,
# fuzzes at the lowest CPU priority and prints libFuzzer's final figures. A finding is left in
# the work folder's artifacts/ (minimise it with the binary's -minimize_crash=1).
#   tools/fuzz.sh TARGET [MINUTES] [libFuzzer options...]
#   TARGET: plot_line track_line truth_line profile scenario plot_batch asterix
#   FUZZ_WORK (default /tmp/skytrack-fuzz), SKYTRACK_FUZZ_BUILD_DIR (default build-fuzz)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
target=${1:?usage: tools/fuzz.sh TARGET [MINUTES] [libFuzzer options...]}
minutes=${2:-30}
shift $(($# < 2 ? $# : 2))
build_dir=${SKYTRACK_FUZZ_BUILD_DIR:-$root/build-fuzz}
work=${FUZZ_WORK:-/tmp/skytrack-fuzz}/$target

case $target in
  plot_line | track_line | truth_line | plot_batch) seeds=$root/fuzz/seeds/$target max_len=4096 ;;
  profile | scenario) seeds=$root/fuzz/seeds/$target max_len=8192 ;;
  asterix) seeds=$root/fuzz/corpus max_len=4096 ;;
  *) echo "unknown target '$target'" >&2; exit 2 ;;
esac

"$root/tools/install-deps.sh"
"$root/tools/install-clang.sh"

launcher=()
command -v ccache >/dev/null &&
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSKYTRACK_FUZZ=ON \
  -DSKYTRACK_TESTS=OFF "${launcher[@]}" >/dev/null
cmake --build "$build_dir" --target "${target}_fuzz" -j"${JOBS:-2}"

rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts"
find "$seeds" -maxdepth 1 -type f ! -name '*.md' -exec cp {} "$work/corpus/" \;
cd "$work"
# -jobs=1: one worker process, its output in fuzz-0.log; the run ends at the first finding.
set +e
nice -n 19 "$build_dir/fuzz/${target}_fuzz" -max_total_time=$((minutes * 60)) -jobs=1 \
  -max_len=$max_len -timeout=30 -print_final_stats=1 -artifact_prefix="$work/artifacts/" \
  "$@" corpus
status=$?
set -e
grep -E '^#[0-9]+ +(DONE|pulse)|^stat::|ERROR|SUMMARY|invariant broken' fuzz-0.log | tail -12
ls "$work/artifacts"
exit $status
