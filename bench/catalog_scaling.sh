#!/usr/bin/env bash
# Recognition as the catalog grows: for catalogs of the first N parts of config/parts-250.yaml
# (25: the default catalog; 100: with 75 more CGAL and procedural parts; 251: every part,
# with the size families of three sizes 10 % apart), builds the model base (once: kept in the
# output folder and reused while its catalog is unchanged and it loads; --rebuild builds
# anew, as after a change to the model-base builder), times its loading and how long until a
# first scan is recognized (`cosmos recognize` of one scan: the file read, the recognizer's
# per-part search models built, one recognition),
# runs the seeded `cosmos eval` on one thread under /usr/bin/time, and prints the table:
# parts, base MB and MB per part, build wall and CPU s per part, load s, ready s, recognition median / p99 / max ms,
# identification, wrong-part rate, size variants told apart, known scans that searched every
# part, and the eval's peak RSS.
#
#   bench/catalog_scaling.sh [--sizes 25,100,251] [--tests N] [--seed S] [--pose random|resting]
#                            [--views V] [--build-threads T] [--out DIR] [--build DIR]
#                            [--rebuild]
#
# Defaults: sizes 25,100,251; 2,000 tests; seed 1; random poses; 320 views; every core for
# the builds; output in build/catalog-scaling. Speed is measured here, never asserted: the
# machine's load shows in the times, so compare runs from the same machine. The meshes come
# from scripts/fetch_catalog.sh and `cosmos catalog procedural` (run here when missing).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

sizes=25,100,251
tests=2000
seed=1
pose=random
views=320
build_threads=$(nproc)
build=$root/build
out=
rebuild=0
while (($#)); do
  case $1 in
    --sizes) sizes=$2; shift 2 ;;
    --tests) tests=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --pose) pose=$2; shift 2 ;;
    --views) views=$2; shift 2 ;;
    --build-threads) build_threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --rebuild) rebuild=1; shift ;;
    *) echo "catalog_scaling: unknown option $1 (see the header of $0)" >&2; exit 2 ;;
  esac
done
out=${out:-$build/catalog-scaling}
cosmos=$build/apps/cosmos
[[ -x $cosmos ]] || { echo "catalog_scaling: $cosmos: not built (scripts/build.sh)" >&2; exit 2; }
[[ -x /usr/bin/time ]] || { echo "catalog_scaling: /usr/bin/time: missing (apt-get install time)" >&2; exit 2; }
mkdir -p "$out"
full_catalog=$root/config/parts-250.yaml
total=$(grep -c '^  - {name:' "$full_catalog")
# The procedural parts live in the mesh cache; `cosmos catalog list` says whether every mesh loads.
if "$cosmos" catalog list --catalog "$full_catalog" 2> /dev/null | grep -q 'procedural/.* FAILS'; then
  "$cosmos" catalog procedural > "$out/procedural.log"
fi

# kB of "Maximum resident set size" and seconds of "Elapsed (wall clock)" from /usr/bin/time -v.
max_rss_kb() { awk -F': ' '/Maximum resident set size/ {print $2}' "$1"; }
wall_s() {
  awk -F': ' '/Elapsed \(wall clock\)/ {
    n = split($2, p, ":"); s = 0; for (i = 1; i <= n; ++i) s = s * 60 + p[i]; print s }' "$1"
}

# The scan the ready time recognizes: a catalog part every base holds, in a random pose.
ready_scan=$out/ready-scan.tif
"$cosmos" sim scan --catalog "$full_catalog" --part cow --random-pose --seed "$seed" \
  --out "$ready_scan" > "$out/ready-scan.log" 2>&1

rows=()
IFS=, read -r -a size_list <<< "$sizes"
for n in "${size_list[@]}"; do
  [[ $n =~ ^[1-9][0-9]*$ && $n -le $total ]] ||
    { echo "catalog_scaling: --sizes: $n is not a part count in 1..$total" >&2; exit 2; }
  catalog=$out/parts-$n.yaml
  {
    echo "# The first $n parts of config/parts-250.yaml."
    echo "parts:"
    grep -m "$n" '^  - {name:' "$full_catalog"
  } > "$catalog.new"
  base=$out/parts-$n-$views.cmb
  # A base is rebuilt when asked, when its catalog changed, or when it does not load (an older
  # format).
  if ((!rebuild)) && [[ -f $base && -f $catalog ]] && cmp -s "$catalog" "$catalog.new" &&
    "$cosmos" modelbase info "$base" > /dev/null 2>&1; then
    rm "$catalog.new"
  else
    mv "$catalog.new" "$catalog"
    echo "catalog_scaling: building the $n-part base ($views views)" >&2
    /usr/bin/time -v -o "$out/build-$n.time" "$cosmos" modelbase build --catalog "$catalog" \
      --views "$views" --threads "$build_threads" --out "$base" > "$out/build-$n.log" 2>&1
  fi
  build_s=$(wall_s "$out/build-$n.time")
  build_cpu_s=$(awk -F': ' '/(User|System) time/ {s += $2} END {print s}' "$out/build-$n.time")
  /usr/bin/time -v -o "$out/load-$n.time" "$cosmos" modelbase info "$base" > "$out/info-$n.txt"
  load_s=$(wall_s "$out/load-$n.time")
  /usr/bin/time -v -o "$out/ready-$n.time" "$cosmos" recognize --modelbase "$base" "$ready_scan" \
    > "$out/ready-$n.txt"
  ready_s=$(wall_s "$out/ready-$n.time")
  echo "catalog_scaling: $tests $pose-pose scans of the $n-part base" >&2
  rm -rf "$out/eval-$n"
  /usr/bin/time -v -o "$out/eval-$n.time" "$cosmos" eval --modelbase "$base" --catalog "$catalog" \
    --tests "$tests" --seed "$seed" --pose "$pose" --threads 1 --out "$out/eval-$n" \
    > "$out/eval-$n.log" 2>&1
  rows+=("$(python3 - "$out/eval-$n" "$n" "$(stat -c %s "$base")" "$build_s" "$build_cpu_s" "$load_s" \
    "$ready_s" \
    "$(max_rss_kb "$out/eval-$n.time")" <<'PY'
import json, sys
folder, parts, base_bytes, build_s, build_cpu_s, load_s, ready_s, rss_kb = sys.argv[1:]
parts = int(parts)
metrics = json.load(open(f"{folder}/metrics.json"))
confusions = json.load(open(f"{folder}/confusions.json"))
known = [r for r in json.load(open(f"{folder}/tests.json")) if r["truth_in_model_base"]]
times = sorted(r["recognition_ms"] for r in known)
def rank(p):  # nearest rank, as the eval's own percentiles
    return times[max(1, -(-len(times) * p // 100)) - 1]
catalog_searched = sum(r["catalog_searched"] for r in known) / len(known)
told = metrics["size_variants"]["told_apart_rate"]
mb = int(base_bytes) / 1e6
def pct(x): return "-" if x is None else f"{100 * x:.2f}"
print(f"{parts:>5} {mb:>8.1f} {mb / parts:>7.2f} {float(build_s) / parts:>7.1f} "
      f"{float(build_cpu_s) / parts:>7.1f} "
      f"{float(load_s):>6.2f} {float(ready_s):>7.2f} {rank(50):>7.1f} {rank(99):>7.1f} {times[-1]:>7.1f} "
      f"{pct(metrics['identification_rate']):>6} {pct(confusions['wrong_part_rate']):>6} "
      f"{pct(told):>6} {pct(catalog_searched):>6} {int(rss_kb) / 1024:>7.0f}")
PY
)")
done

echo "catalog scaling: $tests $pose-pose scans per catalog, seed $seed, $views views, one recognition thread"
echo "parts  base_MB MB/part build_s cpu_s load_s ready_s  med_ms  p99_ms  max_ms  ident%  wrong% sizes% every% rss_MB"
printf '%s\n' "${rows[@]}"
echo "(build_s, cpu_s: the base's build, wall and CPU seconds per part, with $build_threads threads; load_s: the base file read; ready_s: read, the recognizer made, one scan recognized; ident%, wrong%: of known scans; sizes%: size variants told apart; every%: known scans that searched every part; rss_MB: the eval's peak)"
