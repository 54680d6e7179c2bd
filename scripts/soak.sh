#!/usr/bin/env bash
# Soak: the paced simulated cell for a long time with faults injected, its memory watched.
#
#   scripts/soak.sh [--minutes M] [--warmup-minutes W] [--sample-s S] [--build DIR]
#                   [--config FILE] [--hardware FILE] [--out DIR] [--no-faults]
#
# Runs `cosmos cell --repeat` (the simulated belt started over at its end, so the run lasts as
# long as asked) paced at the line rate for M minutes of scanning (default 60), with the
# fault plan below appended to a copy of the config (unless --no-faults, or the config has a
# `faults:` section of its own). The cell's RSS is sampled every S seconds (default 60). At the
# end it prints the RSS samples, the RSS growth from the end of the warm-up (default 5 min)
# to the end, the lowest of the first 10 minutes' samples against the lowest of the last 10
# (the figure that must stay flat: at most 1 %), the poses by status and every
# counter of the cell's last COSMOS_STATUS (its summary), and exits non-zero if the cell
# crashed or RSS grew by more than 1 %. Logs stay in DIR (default build/soak). With
# --hardware config/hardware-sim.yaml the cell runs the hardware path on the simulated twins,
# which inject the faults at the devices (and bounce the photo eye).
set -euo pipefail

minutes=60
warmup_minutes=5
sample_s=60
build=build
config=config/cell.yaml
out=
faults=1
hardware=
while [[ $# -gt 0 ]]; do
  case "$1" in
    --minutes) minutes=$2; shift 2 ;;
    --warmup-minutes) warmup_minutes=$2; shift 2 ;;
    --sample-s) sample_s=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --config) config=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --hardware) hardware=$2; shift 2 ;;
    --no-faults) faults=0; shift ;;
    *) echo "soak.sh: unknown option $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
out=${out:-$build/soak}
cosmos=$build/apps/cosmos
[[ -x $cosmos ]] || { echo "soak.sh: $cosmos: not built (cmake --build $build --target cosmos)" >&2; exit 2; }
[[ -f $config ]] || { echo "soak.sh: $config: no such config" >&2; exit 2; }
mkdir -p "$out"

# The config, with its catalog made absolute (it is relative to the config's directory).
config_dir=$(cd "$(dirname "$config")" && pwd)
soak_config=$out/soak-cell.yaml
sed -E "s|^(  catalog: *)([^/\"][^ ]*)\$|\\1$config_dir/\\2|" "$config" > "$soak_config"
if [[ $faults == 1 ]] && ! grep -q '^faults:' "$soak_config"; then
  # Every fault of the simulated source, each recurring within every pass of the belt (the
  # fault plan counts profiles from the start of the pass; 20 parts are ~6,000 profiles,
  # 2.4 s at 2,500 profiles a second): the cell must count each, fault the affected parts,
  # and go on.
  cat >> "$soak_config" <<'YAML'

faults:
  seed: 11
  frame_gaps: {every_profiles: 2000, profiles: 4}
  camera_stalls: {every_profiles: 3000, profiles: 500}
  encoder_glitches: {every_profiles: 2500, profiles: 2}
  encoder_reversals: {every_profiles: 2900, profiles: 25}
  encoder_stuck: {every_profiles: 2800, profiles: 40}
  laser_off: {every_profiles: 2200, profiles: 60}
  photo_eye_bounces: {every_profiles: 2000, profiles: 500}
YAML
fi

duration_s=$((minutes * 60))
log=$out/cell.log
rss_log=$out/rss.tsv
echo "soak: $minutes min of scanning${hardware:+ on the hardware path ($hardware)}, faults $([[ $faults == 1 ]] && echo on || echo off), config $soak_config, logs in $out"
source_options=()
[[ -n $hardware ]] && source_options=(--source hardware --hardware "$hardware")
"$cosmos" cell --config "$soak_config" "${source_options[@]}" --repeat --duration-s "$duration_s" \
  > "$log" 2> "$out/cell.err" &
pid=$!
trap 'kill $pid 2>/dev/null || true' INT TERM

# Overload skips line periods, so scanning time can trail wall time: allow half as long again.
deadline=$((SECONDS + duration_s * 3 / 2 + 600))
printf 'minute\trss_kb\n' > "$rss_log"
start=$SECONDS
while kill -0 $pid 2>/dev/null; do
  rss=$(ps -o rss= -p $pid 2>/dev/null | tr -d ' ' || true)
  [[ -n $rss && $rss != 0 ]] && printf '%.1f\t%s\n' "$(echo "($SECONDS - $start) / 60" | bc -l)" "$rss" >> "$rss_log"
  if (( SECONDS > deadline )); then
    echo "soak: the cell is still running past its deadline; stopping it" >&2
    kill $pid
  fi
  for ((i = 0; i < sample_s && SECONDS <= deadline; ++i)); do
    kill -0 $pid 2>/dev/null || break
    sleep 1
  done
done
status=0
failed=0
wait $pid || status=$?

echo "soak: RSS samples (minute, kB):"
column -t "$rss_log" | sed 's/^/  /'
# The level at each end is the floor of the samples in a window (window_minutes, at least one
# sample): the recognizer's buffers come and go with each blob, and how often a sample catches
# one in flight depends on the load; what a leak raises is the floor.
window_minutes=10
growth=$(awk -v warm="$warmup_minutes" -v window="$window_minutes" '
  NR > 1 && $1 >= warm { ++n; minute[n] = $1; rss[n] = $2 }
  END {
    if (n == 0) { print "n/a"; exit }
    for (k = 1; k <= n; ++k) {
      if (k == 1 || minute[k] < minute[1] + window) if (base == "" || rss[k] < base) base = rss[k]
      if (k == n || minute[k] > minute[n] - window) if (end == "" || rss[k] < end) end = rss[k]
    }
    printf "%.2f %d %d", 100 * (end - base) / base, base, end
  }' "$rss_log")
echo "poses by status:"
awk '$1 ~ /^[0-9]+$/ && NF >= 8 { ++count[$3] } END { for (s in count) printf "  %s %d\n", s, count[s] }' "$log"
echo "the cell's summary:"
grep '^cell:' "$log" | sed 's/^/  /' || true
if [[ -s $out/cell.err ]]; then
  echo "the cell's stderr (last lines):"
  tail -5 "$out/cell.err" | sed 's/^/  /'
fi
if [[ $growth == n/a ]]; then
  echo "soak: RSS growth after warm-up: n/a (the run ended before $warmup_minutes min)"
else
  read -r percent base last <<< "$growth"
  echo "soak: RSS growth after warm-up ($warmup_minutes min), floor of the first $window_minutes min" \
    "to floor of the last $window_minutes min: $percent % ($base kB -> $last kB)"
  if awk -v p="$percent" 'BEGIN { exit !(p > 1.0) }'; then
    echo "soak: FAILED: RSS grew by more than 1 % after warm-up" >&2
    failed=1
  fi
fi
if [[ $status != 0 ]]; then
  echo "soak: FAILED: the cell exited with status $status" >&2
  failed=1
fi
(( failed == 0 )) || exit 1
echo "soak: passed"
