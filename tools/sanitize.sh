#!/usr/bin/env bash
# The sanitizer job (docs/hardening.md): a clang build of everything with AddressSanitizer and
# UndefinedBehaviorSanitizer, float-cast-overflow included (-DSKYTRACK_SANITIZE=ON), then the
# whole suite. Any report fails its test: UBSan halts (-fno-sanitize-recover), ASan and its
# leak checker end the test program with an error.
#   tools/sanitize.sh                      # build-sanitize/, 2 jobs
#   JOBS=4 SKYTRACK_BUILD_DIR=/tmp/b tools/sanitize.sh -R Pipeline   # extra args go to ctest
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${SKYTRACK_BUILD_DIR:-$root/build-sanitize}
jobs=${JOBS:-2}
"$root/tools/install-deps.sh"

"$root/tools/install-clang.sh"

launcher=()
command -v ccache >/dev/null &&
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DSKYTRACK_SANITIZE=ON \
  "${launcher[@]}" >/dev/null
cmake --build "$build_dir" -j"$jobs"

# Every DDS participant uses the loopback-only configuration, never Cyclone's default.
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1}
ctest --test-dir "$build_dir" --output-on-failure -j"$jobs" "$@"
