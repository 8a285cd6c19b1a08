#!/usr/bin/env bash
# build-deb.sh BUILD OUT_DIR
#   Makes the Debian package from a finished build with CPack (packaging/CMakeLists.txt) into
#   OUT_DIR and prints its path. CPack installs the build under /usr in a scratch folder, strips
#   the programs, runs dpkg-shlibdeps for the dependencies and writes the .deb; the scratch
#   folder is removed afterwards. Used by lacrima.sh package and by the package tests.
set -euo pipefail
build=$1 out=$2
mkdir -p "$out"
log=$out/cpack.log
if ! cpack --config "$build/CPackConfig.cmake" -B "$out" >"$log" 2>&1; then
  echo "lacrima: cpack failed; last lines of $log:" >&2
  tail -n 40 "$log" >&2
  exit 1
fi
rm -rf "$out/_CPack_Packages"
deb=$(ls -t "$out"/lacrima_*.deb | head -n 1)
echo "$deb"
