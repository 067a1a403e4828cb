#!/usr/bin/env bash
# Installs a build of vivp into an empty prefix, then configures, builds and
# runs examples/ against it as a user's project would: find_package(vivp)
# through CMAKE_PREFIX_PATH, with nothing of the source or build tree on its
# paths. The example exits non-zero when one of its checks fails.
# Usage: scripts/check-install.sh BUILD_DIR
set -euo pipefail
build=$(realpath "${1:?usage: scripts/check-install.sh BUILD_DIR}")
cd "$(dirname "$0")/.."
prefix=$(mktemp -d)
work=$(mktemp -d)
# Kept when a step fails, for a look at what was installed and built.
trap 'if (($? == 0)); then rm -rf "$prefix" "$work";
      else echo "check-install: kept $prefix and $work" >&2; fi' EXIT

cmake --install "$build" --prefix "$prefix" >/dev/null
if hits=$(grep -rlF -e "$PWD" -e "$build" "$prefix/lib/cmake"); then
  echo "check-install: the installed package points into the tree:" >&2
  echo "$hits" >&2
  exit 1
fi
"$prefix/bin/vivp" --help >/dev/null

# The compiler the build used: one C++ ABI for the libraries and the example.
cxx=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
cmake -S examples -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" -j "$(nproc)" -- --no-print-directory
"$work/build/exponential_wall" "$work"
