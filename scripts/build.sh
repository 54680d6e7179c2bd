#!/usr/bin/env bash
# Installs what is missing, configures and builds COSMOS-Cell (Release) into build/. The
# compiler's output goes to build/logs/build.log and is shown only when the build fails.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
build_dir=${COSMOS_BUILD_DIR:-$root/build}
mkdir -p "$build_dir/logs"
log=$build_dir/logs/build.log
if [[ ! -f $build_dir/CMakeCache.txt ]]; then
  echo "build: first build into $build_dir (about 9 minutes on 2 cores; log: $log)"
fi
# ccache: the hardware-only tree and later builds reuse what this one compiled (paths taken
# relative to the source tree, so another build directory hits the same entries).
export CCACHE_BASEDIR=$root
if ! { cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache &&
  cmake --build "$build_dir" --parallel "$(nproc)"; } > "$log" 2>&1; then
  tail -n 100 "$log"
  echo "build: failed (the whole output is in $log)" >&2
  exit 1
fi
