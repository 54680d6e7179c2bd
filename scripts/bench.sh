#!/usr/bin/env bash
# Runs every benchmark of bench/ (one binary per bench/*.cpp, built into build/bench/) with
# repetitions, writes each binary's results as JSON to build/bench-results/NAME.json and
# prints the median of every benchmark. Speed is measured here and never asserted by a test;
# the machine's load shows in the numbers, so compare medians from the same machine.
#
#   scripts/bench.sh [--filter REGEX] [--repetitions N] [--no-build]
#
#   --filter REGEX    run only the benchmarks whose names match (--benchmark_filter); a
#                     binary with no match is skipped
#   --repetitions N   repetitions per benchmark (default 5); the medians are over them
#   --no-build        use the binaries already in the build directory instead of running
#                     scripts/build.sh (set-up, configure, build) first
#
# The real-time benches (recognition_bench, scan_loop_bench) need the regression model base
# at build/test-data/regression-80.cmb (ctest's build_regression_model_base makes it): when
# it is missing it is built here first (5 parts x 80 views). $COSMOS_BENCH_MODEL_BASE names
# another base instead. Every bench that scans catalog parts needs the meshes that
# scripts/setup.sh fetches. $COSMOS_BUILD_DIR overrides the build directory.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${COSMOS_BUILD_DIR:-$root/build}

filter=""
repetitions=5
build=true
while (($#)); do
  case $1 in
    --filter)
      (($# >= 2)) || { echo "bench: --filter needs a REGEX" >&2; exit 2; }
      filter=$2
      shift 2
      ;;
    --repetitions)
      if (($# < 2)) || ! [[ $2 =~ ^[1-9][0-9]*$ ]]; then
        echo "bench: --repetitions needs a positive whole number" >&2
        exit 2
      fi
      repetitions=$2
      shift 2
      ;;
    --no-build)
      build=false
      shift
      ;;
    -h | --help)
      sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'
      exit 0
      ;;
    *)
      echo "bench: unknown argument '$1' (see scripts/bench.sh --help)" >&2
      exit 2
      ;;
  esac
done

if $build; then "$root/scripts/build.sh"; fi

# The binaries, as bench/CMakeLists.txt makes them: one per bench/*.cpp, named after it.
names=()
for source in "$root"/bench/*.cpp; do names+=("$(basename "$source" .cpp)"); done

results_dir=$build_dir/bench-results
mkdir -p "$results_dir"
default_base=$build_dir/test-data/regression-80.cmb
model_base=${COSMOS_BENCH_MODEL_BASE:-$default_base}

# The benchmarks of a binary that the filter selects, one per line (none: the binary is
# skipped). Listing runs no benchmark and no fixture.
selected() {
  local binary=$1
  if [[ -n $filter ]]; then
    "$binary" --benchmark_list_tests=true --benchmark_filter="$filter" 2> /dev/null
  else
    "$binary" --benchmark_list_tests=true 2> /dev/null
  fi
}

ensure_model_base() {
  [[ -f $model_base ]] && return 0
  if [[ -n ${COSMOS_BENCH_MODEL_BASE:-} ]]; then
    echo "bench: $model_base: no such model base (\$COSMOS_BENCH_MODEL_BASE)" >&2
    exit 1
  fi
  echo "bench: building the regression model base $model_base"
  mkdir -p "$(dirname "$model_base")"
  "$build_dir/apps/cosmos" modelbase build --catalog "$root/config/parts-regression.yaml" \
    --views 80 --out "$model_base.partial"
  mv "$model_base.partial" "$model_base"
}

failed=()
ran=0
for name in "${names[@]}"; do
  binary=$build_dir/bench/$name
  if [[ ! -x $binary ]]; then
    echo "bench: $binary: not built (run without --no-build, or build the target $name)" >&2
    exit 1
  fi
  if ! list=$(selected "$binary"); then
    failed+=("$name")
    echo "bench: $binary --benchmark_list_tests failed" >&2
    continue
  fi
  if [[ -z $list ]]; then continue; fi
  case $name in
    recognition_bench | scan_loop_bench) ensure_model_base ;;
  esac
  json=$results_dir/$name.json
  console=$results_dir/$name.txt
  arguments=(--benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true
    --benchmark_out="$json" --benchmark_out_format=json --benchmark_color=false)
  if [[ -n $filter ]]; then arguments+=(--benchmark_filter="$filter"); fi
  echo "== $name -> $json"
  ran=$((ran + 1))
  if ! COSMOS_BENCH_MODEL_BASE=$model_base "$binary" "${arguments[@]}" > "$console" 2>&1; then
    failed+=("$name")
    echo "bench: $name failed; its output is in $console" >&2
    tail -n 5 "$console" >&2
    continue
  fi
  # The console table's header and its median rows (the JSON holds every aggregate); a
  # benchmark that skipped itself (e.g. no catalog meshes) says why.
  grep -m 1 '^Benchmark ' "$console" || true
  grep -E '_median ' "$console" || echo "(no medians: see $console)"
  grep 'ERROR OCCURRED' "$console" | sort -u >&2 || true
done

if ((ran == 0)); then
  echo "bench: no benchmark matches '${filter}'" >&2
  exit 1
fi
if ((${#failed[@]})); then
  echo "bench: failed: ${failed[*]}" >&2
  exit 1
fi
echo "bench: $ran binaries, results in $results_dir"
