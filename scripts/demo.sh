#!/usr/bin/env bash
# The README's main job: the simulated work cell with the default configuration. Catalog parts
# at random poses ride the simulated conveyor past the laser-line scanner at the configured
# line rate; each part is recognized and its pose published over LCM (COSMOS_POSE) while a
# live table shows it; a summary ends the run. The first run builds the model base of the
# default catalog (25 parts from 320 directions: about 2.5 minutes on 2 cores) and caches it.
# Extra arguments go to `cosmos cell` (e.g. --parts 5, --unpaced). The set-up and the build
# print a line per step only (their output goes to build/logs/), so the table comes first.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build_dir=${COSMOS_BUILD_DIR:-$root/build}
exec "$build_dir/apps/cosmos" cell --config "$root/config/cell.yaml" "$@"
