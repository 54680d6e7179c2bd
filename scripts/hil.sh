#!/usr/bin/env bash
# The hardware bridge against real kernel drivers (docs/hil.md): boots Debian's 6.1 kernel
# under qemu (TCG: no KVM needed) with a small initramfs, and inside runs the project's
# V4l2Camera against the vivid capture node and its libgpiod lines against a gpio-sim chip,
# driven by the simulated conveyor's frames and encoder, then the whole cell on them.
#
# It installs what is missing (scripts/hil/host_packages.sh, scripts/setup.sh), builds the
# binaries it needs, fetches the kernel and builds gpio-sim (cached by kernel release under
# ${COSMOS_CACHE_DIR:-~/.cache/cosmos-cell}/hil), and writes its work files, the guest's
# console and the log of every download and build under ${COSMOS_BUILD_DIR:-build}/hil.
# Exits 0 only when the guest booted and every check passed; when the guest cannot boot it
# says why in one line and fails.
#
# Environment: HIL_STEPS (comma-separated guest steps, default all:
# loop,lifecycle,formats,gpio,faults,cell),
# HIL_PARTS (parts on the cell's conveyor, default 10),
# HIL_TIMEOUT_S (the guest's wall-clock limit, default 1800).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build_dir=${COSMOS_BUILD_DIR:-$root/build}
hil_cache=${COSMOS_CACHE_DIR:-$HOME/.cache/cosmos-cell}/hil
work=$build_dir/hil
steps=${HIL_STEPS:-loop,lifecycle,formats,gpio,faults,cell}
parts=${HIL_PARTS:-10}
timeout_s=${HIL_TIMEOUT_S:-1800}
mkdir -p "$work" "$hil_cache"
log=$work/hil.log
: > "$log"
started=$(date +%s)

say() { echo "hil: $*"; }
fail() {
  echo "hil: FAIL $*" >&2
  exit 1
}
elapsed() { echo $(($(date +%s) - started)); }

"$root/scripts/hil/host_packages.sh" "$log"
command -v qemu-system-x86_64 > /dev/null ||
  fail "the guest cannot boot: qemu-system-x86_64 is not on PATH after installing qemu-system-x86"
"$root/scripts/setup.sh" >> "$log" 2>&1 || fail "scripts/setup.sh failed (see $log)"
cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >> "$log" 2>&1 ||
  fail "configuring $build_dir failed (see $log)"
cmake --build "$build_dir" --parallel "$(nproc)" --target cosmos hil_probe hil_player hil_render hil_check >> "$log" 2>&1 ||
  fail "building cosmos and the HIL tools failed (see $log)"
say "built cosmos and the HIL tools ($(elapsed) s)"

kernel_dir=$("$root/scripts/hil/fetch_kernel.sh" "$hil_cache" "$log")
"$root/scripts/hil/build_gpio_sim.sh" "$kernel_dir" "$log"
say "kernel $(basename "$kernel_dir") ($(< "$kernel_dir/package") $(< "$kernel_dir/version")) with gpio-sim built out of tree ($(elapsed) s)"

base=$work/regression-80.cmb
[[ -f $base && $root/config/parts-regression.yaml -nt $base ]] && rm -f "$base"
# The unit tests' copy of the same base (ctest builds it), when there is one.
tests_base=$build_dir/test-data/regression-80.cmb
if [[ ! -f $base && -f $tests_base && $tests_base -nt $root/config/parts-regression.yaml ]]; then
  cp "$tests_base" "$base"
fi
if [[ ! -f $base ]]; then
  "$build_dir/apps/cosmos" modelbase build --catalog "$root/config/parts-regression.yaml" \
    --views 80 --out "$base.partial" >> "$log" 2>&1 || fail "building the model base failed (see $log)"
  mv "$base.partial" "$base"
fi
# The conveyors the guest plays, recorded here: the guest would draw them far too slowly.
render() {
  local tape=$1 parts=$2
  local inputs=("$build_dir/tests/hil/hil_render" "$root/config/cell-hil.yaml"
    "$root/config/hardware-hil.yaml" "$root/config/parts-regression.yaml")
  local input
  if [[ -f $tape ]]; then
    for input in "${inputs[@]}"; do [[ $input -nt $tape ]] && rm -f "$tape"; done
  fi
  [[ -f $tape ]] && return 0
  "$build_dir/tests/hil/hil_render" --config "$root/config/cell-hil.yaml" \
    --hardware "$root/config/hardware-hil.yaml" --parts "$parts" --out "$tape" >> "$log" 2>&1 ||
    fail "recording the conveyor of $parts parts failed (see $log)"
}
render "$work/cell-$parts.tape" "$parts"
render "$work/probe-2.tape" 2
"$root/scripts/hil/make_initramfs.sh" "$work/initramfs.cpio" "$kernel_dir" "$build_dir" "$base" \
  "$work/cell-$parts.tape" "$work/probe-2.tape"
say "initramfs $(($(stat -c %s "$work/initramfs.cpio") / 1048576)) MiB ($(elapsed) s)"

# The binaries use AVX2 and FMA (COSMOS_AVX2): qemu's TCG emulates them when asked.
cpu=max,+avx,+avx2,+fma
# The guest's clock runs on its instructions, not on the host's: -icount shift=0 makes every
# emulated instruction one nanosecond (a 1 GHz CPU whatever the host), sleep=off skips the
# time the guest idles. Emulated, the cell's floating point runs hundreds of times slower
# than on the host, and a guest on the host's clock falls behind vivid's frame rate; on its
# own clock it keeps up, however slow or loaded the host, which then only takes longer.
# icount runs one emulated CPU (with two, the secondary CPU never comes up).
clock=(-icount shift=0,sleep=off -smp 1)
console=$work/console.log
up_stamp=$work/guest-up-at
rm -f "$up_stamp"
boot_started=$(date +%s)
set +e
timeout --kill-after=10 "$timeout_s" qemu-system-x86_64 -accel tcg "${clock[@]}" -cpu "$cpu" -m 3072 \
  -display none -monitor none -serial stdio -no-reboot -nic none \
  -kernel "$kernel_dir/vmlinuz" -initrd "$work/initramfs.cpio" \
  -append "console=ttyS0 quiet panic=-1 hil_steps=$steps hil_parts=$parts" < /dev/null 2>&1 |
  stdbuf -oL tr -d '\r' | tee "$console" | grep -a --line-buffered -E '^(hil|cell): ' |
  while IFS= read -r line; do
    # The boot ends where /init first speaks (tr line-buffered, so that the line arrives then).
    [[ $line == "hil: guest up"* && ! -f $up_stamp ]] && date +%s > "$up_stamp"
    printf '%s\n' "$line"
  done
qemu_status=${PIPESTATUS[0]}
set -e
guest_s=$(($(date +%s) - boot_started))
say "guest ran $guest_s s (whole run $(elapsed) s)"

if ! grep -aq '^hil: guest up' "$console"; then
  last=$(grep -av '^\s*$' "$console" | tail -n 1)
  if ((qemu_status == 124)); then
    fail "the guest did not boot within ${timeout_s} s (last console line: ${last:-none})"
  fi
  fail "the guest did not boot: qemu exited with status $qemu_status (last console line: ${last:-none})"
fi
exit_line=$(grep -a '^hil: guest exit' "$console" | tail -n 1 || true)
if [[ -z $exit_line ]]; then
  ((qemu_status == 124)) && fail "the guest did not finish within ${timeout_s} s (console: $console)"
  fail "the guest stopped before its checks finished (console: $console)"
fi
boot_s=$(($(< "$up_stamp") - boot_started))
say "summary: boot $boot_s s (qemu start to /init), checks $((guest_s - boot_s)) s, whole run $(elapsed) s"
# The cell step's figures (hil_check): parts, ADD-S, frames, gaps and the COSMOS_STATUS totals.
grep -a '^hil: INFO summary: ' "$console" | sed 's/^hil: INFO summary: /hil: summary: /' || true
grep -a -E '^hil: FAIL ' "$console" | sed 's/^hil: FAIL /hil: summary: failed: /' || true
failed=${exit_line##* }
((failed == 0)) || fail "$failed guest step(s) failed (console: $console)"
say "PASS all steps ($steps)"
