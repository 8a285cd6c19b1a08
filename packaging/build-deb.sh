#!/usr/bin/env bash
# build-deb.sh BUILD OUT_DIR
#   Makes the Debian package from a finished build with CPack (packaging/CMakeLists.txt) into
#   OUT_DIR and prints its path. CPack installs the build under /usr in a scratch folder, strips
#   the programs, runs dpkg-shlibdeps for the dependencies and writes the .deb; the scratch
#   folder is removed afterwards. Used by lacrima.sh package and by the package tests.
#   BUILD must have been configured with Debian's hardening flags (below); if not, it stops
#   and says how to configure it.
# build-deb.sh --cmake-flags
#   Prints the CMake arguments that carry those flags, one a line. lacrima.sh configures
#   ./build with them, so the package is made from the build its tests ran.
# build-deb.sh --check BUILD
#   Succeeds when BUILD was configured with them.
set -euo pipefail

# Debian's hardening flags from dpkg-buildflags (hardening=+all: fortify, stack protector,
# format checks, RELRO, BIND_NOW; PIE is GCC's default on Debian). Left out: -g and -O2, since
# the programs are stripped and the Release build type adds -O3; the file and debug prefix
# maps, which would name the folder this script was called from and matter only for debug
# information. The project compiles only C++, so CFLAGS has nothing to build; CPPFLAGS goes
# with CXXFLAGS, since CMake has no separate preprocessor flags.
cmake_flags() {
  local -x DEB_BUILD_MAINT_OPTIONS="hardening=+all reproducible=-fixfilepath,-fixdebugpath"
  local -x DEB_CXXFLAGS_MAINT_STRIP="-g -O2"
  local cppflags cxxflags ldflags
  cppflags=$(dpkg-buildflags --get CPPFLAGS)
  cxxflags=$(dpkg-buildflags --get CXXFLAGS)
  ldflags=$(dpkg-buildflags --get LDFLAGS)
  printf '%s\n' "-DCMAKE_CXX_FLAGS=$cppflags $cxxflags" \
    "-DCMAKE_EXE_LINKER_FLAGS=$ldflags" "-DCMAKE_SHARED_LINKER_FLAGS=$ldflags" \
    "-DCMAKE_MODULE_LINKER_FLAGS=$ldflags"
}

# Whether each -DNAME=VALUE above is NAME:TYPE=VALUE in the cache of build $1; names the first
# one that is not.
configured_with_flags() {
  local flag name cached
  [ -f "$1/CMakeCache.txt" ] || { missing="no CMakeCache.txt"; return 1; }
  while IFS= read -r flag; do
    name=${flag#-D} name=${name%%=*}
    cached=$(sed -n "s/^$name:[A-Z]*=//p" "$1/CMakeCache.txt")
    if [ "$cached" != "${flag#*=}" ]; then
      missing=$name
      return 1
    fi
  done < <(cmake_flags)
}

case "${1:-}" in
  --cmake-flags) cmake_flags; exit 0 ;;
  --check) configured_with_flags "$2"; exit $? ;;
esac
build=$1 out=$2

missing=
if ! configured_with_flags "$build"; then
  echo "lacrima: $build was not configured with Debian's hardening flags ($missing);" \
    "configure it with the arguments of 'bash packaging/build-deb.sh --cmake-flags'" \
    "(bash packaging/lacrima.sh build does) and build it again" >&2
  exit 1
fi

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
