#!/usr/bin/env bash
# Packs the guest's initramfs (an uncompressed newc cpio: the guest unpacks it faster than it
# would decompress it under TCG): busybox as the shell and init's tools, the kernel modules
# (vivid's chain, configfs, irq_sim and gpio-sim), the project's `cosmos` binary and the
# HIL tools with every shared library they load (ldd), lcm-logger, the HIL configuration with
# the regression catalog, its meshes and its model base, the recorded conveyors (hil_render)
# and the test script as /init.
#
# Usage: make_initramfs.sh OUT_FILE KERNEL_DIR BUILD_DIR MODEL_BASE CELL_TAPE PROBE_TAPE
set -euo pipefail
out=$1
kernel_dir=$2
build_dir=$3
model_base=$4
cell_tape=$5
probe_tape=$6
root=$(cd "$(dirname "$0")/../.." && pwd)

fail() {
  echo "hil: $*" >&2
  exit 1
}

staging=$(mktemp -d "${TMPDIR:-/tmp}/cosmos-hil-initramfs.XXXXXX")
trap 'rm -rf "$staging"' EXIT
mkdir -p "$staging"/{bin,dev,proc,sys,tmp,run,etc,lib/modules/hil,opt/cosmos/bin,opt/cosmos/config,opt/cosmos/tapes}
cp "$kernel_dir/busybox" "$staging/bin/busybox"
cp "$kernel_dir"/modules/*.ko "$kernel_dir/gpio-sim"/*.ko "$staging/lib/modules/hil/"
{
  cat "$kernel_dir/modules/load-order"
  echo irq_sim.ko
  echo gpio-sim.ko
} > "$staging/lib/modules/hil/load-order"

binaries=("$build_dir/apps/cosmos" "$build_dir/tests/hil/hil_probe" "$build_dir/tests/hil/hil_player"
  "$build_dir/tests/hil/hil_check")
lcm_logger=$(command -v lcm-logger) || fail "lcm-logger not found (Debian package liblcm-bin)"
binaries+=("$lcm_logger")
for binary in "${binaries[@]}"; do
  [[ -x $binary ]] || fail "$binary is missing (was it built?)"
  cp "$binary" "$staging/opt/cosmos/bin/"
  # Every library the dynamic loader maps, at the path it maps it from.
  for library in $(ldd "$binary" | awk '/=> \// {print $3} /^\t\/.*ld-linux/ {print $1}'); do
    if [[ ! -e $staging$library ]]; then
      mkdir -p "$staging$(dirname "$library")"
      cp -L "$library" "$staging$library"
    fi
  done
done

cp "$root/config/cell-hil.yaml" "$root/config/hardware-hil.yaml" "$root/config/parts-regression.yaml" \
  "$staging/opt/cosmos/config/"
cp "$model_base" "$staging/opt/cosmos/config/regression-80.cmb"
cp "$cell_tape" "$staging/opt/cosmos/tapes/cell.tape"
cp "$probe_tape" "$staging/opt/cosmos/tapes/probe.tape"
mesh_dir=${COSMOS_CACHE_DIR:-$HOME/.cache/cosmos-cell}/meshes
mkdir -p "$staging/opt/cosmos/cache/meshes"
for mesh in $(sed -n 's/.*mesh: *\([^,}]*\).*/\1/p' "$root/config/parts-regression.yaml"); do
  [[ -f $mesh_dir/$mesh ]] || fail "mesh $mesh of config/parts-regression.yaml not in $mesh_dir"
  cp "$mesh_dir/$mesh" "$staging/opt/cosmos/cache/meshes/"
done

cp "$root/scripts/hil/guest_init.sh" "$staging/init"
chmod 755 "$staging/init"
(cd "$staging" && find . -print | "$kernel_dir/busybox" cpio -o -H newc 2> /dev/null) > "$out.partial"
mv "$out.partial" "$out"
