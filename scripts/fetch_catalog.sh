#!/usr/bin/env bash
# Fetches the default part catalog's meshes: Debian's libcgal-demo package ships CGAL's
# sample data, and its data/meshes/ folder holds the free-form and mechanical parts that
# config/parts.yaml names. The meshes go to a cache outside the repository (they are never
# committed): ${COSMOS_CACHE_DIR:-$HOME/.cache/cosmos-cell}/meshes.
#
# The package is only downloaded (apt-get download), never installed. Its data/meshes/
# folder is not a file of the package itself but sits inside a nested tarball
# (usr/share/doc/libcgal-dev/data.tar.gz in Debian 12), so both layouts are handled.
#
# Idempotent: a stamp file records the package version; nothing is downloaded when the
# stamp matches the version apt would fetch.
set -euo pipefail

package=libcgal-demo
cache_root=${COSMOS_CACHE_DIR:-$HOME/.cache/cosmos-cell}
mesh_dir=$cache_root/meshes
stamp=$mesh_dir/.libcgal-demo-version

fail() {
  echo "fetch_catalog: $*" >&2
  exit 1
}

# The version apt would download; empty when the package index does not know the package
# (no `apt-get update` yet), in which case an existing cache is kept as it is.
candidate=$(apt-cache policy "$package" 2>/dev/null | awk '/Candidate:/ {print $2}')
if [[ $candidate == "(none)" ]]; then candidate=""; fi

if [[ -f $stamp ]]; then
  have=$(<"$stamp")
  if [[ -z $candidate || $candidate == "$have" ]]; then
    echo "fetch_catalog: meshes of $package $have already in $mesh_dir"
    exit 0
  fi
fi

for tool in apt-get dpkg-deb tar; do
  command -v "$tool" > /dev/null || fail "'$tool' not found (this script needs Debian's apt and dpkg)"
done

work=$(mktemp -d "${TMPDIR:-/tmp}/cosmos-fetch-catalog.XXXXXX")
trap 'rm -rf "$work"' EXIT

# apt-get download writes into the current directory; as root it warns that the _apt user
# cannot write the private temp dir, which is harmless, so its output is shown only on failure.
if ! (cd "$work" && apt-get download -q "$package" > "$work/download.log" 2>&1); then
  cat "$work/download.log" >&2
  fail "'apt-get download $package' failed: is Debian's package index reachable (run 'apt-get update')?"
fi
deb=$(find "$work" -maxdepth 1 -name "${package}_*.deb" | head -n 1)
[[ -n $deb ]] || fail "'apt-get download $package' produced no .deb in $work"
version=$(dpkg-deb -f "$deb" Version)

extract=$work/extract
mkdir -p "$extract"
dpkg-deb --fsys-tarfile "$deb" > "$work/fsys.tar"

# Layout 1: the package holds data/meshes/ directly.
direct=$(tar -tf "$work/fsys.tar" | grep -m 1 -E '(^|/)data/meshes/$' || true)
if [[ -n $direct ]]; then
  tar -xf "$work/fsys.tar" -C "$extract" "$direct"
  meshes=$extract/$direct
else
  # Layout 2: data/meshes/ sits in a nested data.tar.* (Debian 12: .../libcgal-dev/data.tar.gz).
  nested=$(tar -tf "$work/fsys.tar" | grep -m 1 -E '/data\.tar\.(gz|xz|bz2|zst)$' || true)
  [[ -n $nested ]] || fail "$package $version holds neither data/meshes/ nor a nested data.tar.*"
  tar -xf "$work/fsys.tar" -C "$work" "$nested"
  inner=$(tar -tf "$work/$nested" | grep -m 1 -E '(^|/)data/meshes/$' || true)
  [[ -n $inner ]] || fail "$nested of $package $version holds no data/meshes/ folder"
  tar -xf "$work/$nested" -C "$extract" "$inner"
  meshes=$extract/$inner
fi

count=$(find "$meshes" -maxdepth 1 -type f | wc -l)
((count > 0)) || fail "data/meshes/ of $package $version is empty"

# Replace the cache in one rename so an interrupted run never leaves a half-filled folder
# behind a valid stamp.
mkdir -p "$cache_root"
staging=$(mktemp -d "$cache_root/.meshes.XXXXXX")
cp -a "$meshes/." "$staging/"
echo "$version" > "$staging/.libcgal-demo-version"
chmod 755 "$staging"
rm -rf "$mesh_dir"
mv "$staging" "$mesh_dir"
echo "fetch_catalog: $count meshes of $package $version in $mesh_dir"
