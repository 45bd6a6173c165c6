#!/usr/bin/env bash
# Installs dependencies (if missing) and builds skytrack into build/ (Release with debug info).
# Extra arguments go to CMake, e.g. tools/build.sh -DSKYTRACK_SANITIZE=ON.
# The README's two commands (run-default.sh, test.sh) both build through here with the same
# options, so the second reuses the first's build instead of reconfiguring and rebuilding it:
# warnings are errors in this, the project's own build (plain `cmake` builds keep them off).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install-deps.sh"
build_dir=${SKYTRACK_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSKYTRACK_WERROR=ON \
  "$@" >/dev/null
cmake --build "$build_dir" -j"$(nproc)"
