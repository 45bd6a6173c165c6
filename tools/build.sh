#!/usr/bin/env bash
# Installs dependencies (if missing) and builds skytrack into build/ (Release with debug info).
# Extra arguments go to CMake, e.g. tools/build.sh -DSKYTRACK_SANITIZE=ON.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install-deps.sh"
build_dir=${SKYTRACK_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
