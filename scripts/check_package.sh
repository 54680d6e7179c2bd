#!/usr/bin/env bash
# CI step after scripts/test.sh: builds the Debian package (cpack, for the /usr prefix),
# installs it on this machine (dpkg -i, then apt-get -f install for any missing dependency),
# and runs the installed files: `cosmos --version`, the systemd unit through
# `systemd-analyze verify`, the C++ and Java examples built against the installed kit, and a
# 3-part simulated cell on the installed configuration and regression catalog (its model base
# built by the cell itself, 20 views a part). The package is removed again at the end.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
build_dir=${COSMOS_BUILD_DIR:-$root/build}
mkdir -p "$build_dir/logs"
log=$build_dir/logs/check_package.log
: > "$log"
fail() {
  echo "check_package: $*" >&2
  exit 1
}
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
work=$(mktemp -d "${TMPDIR:-/tmp}/cosmos-check-package.XXXXXX")

previous_prefix=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$build_dir/CMakeCache.txt" 2> /dev/null)
cleanup() {
  "${sudo_cmd[@]}" dpkg --purge cosmos-cell >> "$log" 2>&1 || true
  cmake -S "$root" -B "$build_dir" -DCMAKE_INSTALL_PREFIX="${previous_prefix:-/usr/local}" \
    >> "$log" 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT

run() { "$@" >> "$log" 2>&1 || { tail -n 40 "$log" >&2; fail "'$*' failed (log: $log)"; }; }

run cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr
run cmake --build "$build_dir" --parallel "$(nproc)" --target package
deb=$(find "$build_dir/package" -maxdepth 1 -name 'cosmos-cell_*.deb' -newer "$build_dir/CMakeCache.txt" | head -n 1)
[[ -n $deb ]] || fail "cpack produced no cosmos-cell_*.deb in $build_dir/package"
depends=$(dpkg-deb -f "$deb" Depends)
for library in liblcm1 libyaml-cpp; do
  [[ $depends == *"$library"* ]] || fail "$deb: Depends lacks $library: $depends"
done

"${sudo_cmd[@]}" dpkg --purge cosmos-cell >> "$log" 2>&1 || true
if ! "${sudo_cmd[@]}" dpkg -i "$deb" >> "$log" 2>&1; then
  run env DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get -f install -y -qq
fi
dpkg-query -W -f='${Status}' cosmos-cell | grep -q "install ok installed" ||
  fail "cosmos-cell is not installed after dpkg -i and apt-get -f install (log: $log)"

version=$(/usr/bin/cosmos --version)
expected_version=$(sed -n 's/^project(cosmos_cell VERSION \([0-9.]*\).*/\1/p' "$root/CMakeLists.txt")
[[ $version == "cosmos $expected_version ("* ]] || fail "cosmos --version printed '$version'"
for file in /etc/cosmos-cell/cell.yaml /etc/cosmos-cell/parts-regression.yaml \
  /usr/lib/systemd/system/cosmos-cell.service /usr/libexec/cosmos-cell/fetch_catalog.sh \
  /usr/share/java/cosmos_lcm_types.jar /usr/include/cosmos_lcm/part_pose_t.hpp \
  /usr/share/cosmos-cell/clients/cpp/CMakeLists.txt \
  /usr/share/cosmos-cell/clients/java/PoseSubscriber.java; do
  [[ -e $file ]] || fail "the package installed no $file"
done
if command -v systemd-analyze > /dev/null; then
  run systemd-analyze verify /usr/lib/systemd/system/cosmos-cell.service
fi

# The examples as an integrator builds them, against the installed kit only.
run cmake -S /usr/share/cosmos-cell/clients/cpp -B "$work/cpp" -DCMAKE_BUILD_TYPE=Release
run cmake --build "$work/cpp"
mkdir -p "$work/java"
run javac -d "$work/java" -cp /usr/share/java/lcm.jar:/usr/share/java/cosmos_lcm_types.jar \
  /usr/share/cosmos-cell/clients/java/PoseSubscriber.java

# A 3-part simulated cell from the installed files: the meshes setup fetched, the cell's model
# base built into a scratch cache as the service would into /var/lib/cosmos-cell.
/usr/libexec/cosmos-cell/fetch_catalog.sh >> "$log" 2>&1 || fail "the installed fetch_catalog.sh failed"
mkdir -p "$work/cache"
ln -s "${COSMOS_CACHE_DIR:-$HOME/.cache/cosmos-cell}/meshes" "$work/cache/meshes"
cat > "$work/cell.yaml" << YAML
cell:
  catalog: /etc/cosmos-cell/parts-regression.yaml
  model_views: 20
YAML
COSMOS_CACHE_DIR=$work/cache /usr/bin/cosmos cell --config "$work/cell.yaml" --parts 3 --unpaced \
  > "$work/cell.out" 2> "$work/cell.err" ||
  { cat "$work/cell.err" >&2; fail "the installed cosmos cell failed"; }
grep -q "3 poses published" "$work/cell.out" || fail "the installed cell: $(cat "$work/cell.out")"
grep -q "building the model base" "$work/cell.err" || fail "no model-base build announced: $(cat "$work/cell.err")"
echo "check_package: $(basename "$deb") ($(du -h "$deb" | cut -f1)) installs and runs:" \
  "'$version', a 3-part cell, the examples built against the installed kit"
