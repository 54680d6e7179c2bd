#!/usr/bin/env bash
# Installs what is missing, configures and builds COSMOS-Cell (Release) into build/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
build_dir=${COSMOS_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build_dir" --parallel "$(nproc)"
