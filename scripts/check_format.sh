#!/usr/bin/env bash
# Fails when a C++ source of the repository is not formatted by its .clang-format.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if ! command -v clang-format > /dev/null; then
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
  log=${TMPDIR:-/tmp}/cosmos-setup-clang-format.log
  echo "check_format: installing clang-format (log: $log)"
  { "${sudo_cmd[@]}" apt-get update -qq && DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" \
      apt-get install -y -qq --no-install-recommends clang-format; } > "$log" 2>&1
fi
cd "$root"
git ls-files -z '*.cpp' '*.hpp' | xargs -0 clang-format --dry-run --Werror
echo "check_format: $(git ls-files '*.cpp' '*.hpp' | wc -l) files formatted"
