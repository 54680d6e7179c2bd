#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/, clang, ASan + UBSan) into build-fuzz/ and runs each
# for SECONDS (default 60) from the seed corpus the build writes, one per core at a time.
# A crash, leak, timeout or sanitizer report fails the script and leaves the reproducer in
# build-fuzz/fuzz/crashes/<harness>/. Each harness's corpus grows in build-fuzz/fuzz/corpus/.
# Prints per harness: executions, coverage (libFuzzer's cov: edges), corpus size.
# The mutations follow COSMOS_FUZZ_SEED (default 1), so a finding can be reproduced by rerunning.
# COSMOS_FUZZ_RUNS=N also ends each harness after N executions (whichever comes first, N or
# SECONDS), so a long run for a number of executions frees its core as soon as it has them.
#   scripts/fuzz.sh [SECONDS] [HARNESS...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
shift || true
build_dir=${COSMOS_FUZZ_BUILD_DIR:-$root/build-fuzz}
harnesses=(range_image mesh_off mesh_ply mesh_stl mesh_obj cell_config hardware_config
  part_catalog model_base lcm_log lcm_range_profile lcm_part_pose lcm_cell_status)
if (($#)); then harnesses=("$@"); fi

if ! command -v clang++ > /dev/null; then
  echo "fuzz: clang++ not found (scripts/setup.sh installs it)" >&2
  exit 1
fi
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# -O1 without debug information: the build is most of a short run's time.
CC=clang CXX=clang++ cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCOSMOS_FUZZ=ON "${launcher[@]}" > /dev/null
targets=(fuzz_corpus)
for harness in "${harnesses[@]}"; do targets+=("fuzz_$harness"); done
cmake --build "$build_dir" --parallel "${COSMOS_BUILD_JOBS:-$(nproc)}" --target "${targets[@]}"

# One harness: its corpus, reproducers and log; exit status non-zero on a finding.
fuzz_one() {  # HARNESS
  local corpus=$build_dir/fuzz/corpus/$1 crashes=$build_dir/fuzz/crashes/$1
  local log=$build_dir/fuzz/logs/$1.log
  mkdir -p "$corpus" "$crashes" "$(dirname "$log")"
  rm -f "$log.status"
  # Inputs up to 64 KiB, YAML files up to 24 KiB (the largest shipped one, the 250-part
  # catalog, is 20 KiB: longer texts only parse slower); 10 s or 2 GB for one input is a
  # finding too (an unbounded loop or allocation from input).
  local max_len=65536
  case $1 in cell_config | hardware_config | part_catalog) max_len=24576 ;; esac
  local rc=0
  "$build_dir/fuzz/fuzz_$1" "$corpus" -max_total_time="$seconds" -seed="${COSMOS_FUZZ_SEED:-1}" \
    -runs="${COSMOS_FUZZ_RUNS:--1}" \
    -max_len="$max_len" -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$crashes/" -print_final_stats=1 > "$log" 2>&1 || rc=$?
  echo "$rc" > "$log.status"
}

# The harnesses run side by side, one per core (each is one single-threaded process).
parallel=${COSMOS_FUZZ_JOBS:-$(nproc)}
for harness in "${harnesses[@]}"; do
  while (($(jobs -rp | wc -l) >= parallel)); do wait -n || true; done
  fuzz_one "$harness" &
done
wait

status=0
for harness in "${harnesses[@]}"; do
  log=$build_dir/fuzz/logs/$harness.log
  if [[ $(cat "$log.status" 2> /dev/null) != 0 ]]; then
    status=1
    echo "fuzz: $harness FAILED (reproducer in $build_dir/fuzz/crashes/$harness, log $log)" >&2
    grep -m 5 -E "ERROR|SUMMARY|runtime error" "$log" >&2 || true
  fi
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  printf 'fuzz: %-18s %10s executions  %6s edges  %5s corpus files\n' "$harness" \
    "$executions" "$coverage" "$(find "$build_dir/fuzz/corpus/$harness" -type f | wc -l)"
done
exit "$status"
