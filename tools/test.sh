#!/usr/bin/env bash
# The README's test command: install dependencies, build, run the whole suite with ctest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/build.sh" -DSKYTRACK_WERROR=ON
build_dir=${SKYTRACK_BUILD_DIR:-$root/build}
# Every DDS participant uses the loopback-only configuration, never Cyclone's default.
export CYCLONEDDS_URI="file://$root/config/dds/loopback.xml"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)"
