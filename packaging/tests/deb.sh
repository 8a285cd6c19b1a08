#!/usr/bin/env bash
# deb.sh BUILD OUT_DIR
#   Builds the .deb (build-deb.sh) into OUT_DIR, where package_fresh_root picks it up, then
#   checks what a Debian maintainer would: the control fields (dependencies from
#   dpkg-shlibdeps, xvfb recommended), the files it holds, and lintian: no error, and no
#   warning other than those packaging/lintian-warnings.txt lists with their reasons.
set -euo pipefail
build=$1 out=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
. "$here/lib.sh"
need cpack:cmake dpkg-deb:dpkg dpkg-shlibdeps:dpkg-dev lintian:lintian

rm -rf "$out"
start=$SECONDS
deb=$(bash "$here/../build-deb.sh" "$build" "$out")
echo "built $(basename "$deb") in $((SECONDS - start)) s: $(du -k "$deb" | cut -f1) KiB," \
  "$(dpkg-deb -f "$deb" Installed-Size) KiB installed"

depends=$(dpkg-deb -f "$deb" Depends)
recommends=$(dpkg-deb -f "$deb" Recommends)
echo "Depends: $depends"
echo "Recommends: $recommends"
# Libraries only dpkg-shlibdeps can have put there (nothing lists them by hand), with versions.
for library in libqt6core6 libqt6widgets6 libogre1.12.10 libode8 libassimp5 libtinygltf2d \
    libavcodec59 libavformat59 libswscale6 libc6; do
  [[ "$depends" =~ (^|, )$library(:[a-z0-9]+)?\ \(\>= ]] ||
    fail "Depends lacks a versioned $library from dpkg-shlibdeps: $depends"
done
for package in qt6-qpa-plugins curl ca-certificates; do
  [[ "$depends" =~ (^|, )$package(,|$) ]] || fail "Depends lacks $package: $depends"
done
[[ "$recommends" =~ (^|, )xvfb(,|$) ]] || fail "Recommends lacks xvfb: $recommends"

contents=$(dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|')
for path in /usr/bin/lacrima-editor /usr/bin/lacrima-player /usr/bin/lacrima-fap /usr/bin/lacrima-send /usr/bin/lacrima-batch \
    /usr/bin/lacrima-rig /usr/bin/lacrima-fetch-head /usr/libexec/lacrima/lacrima-import \
    /usr/share/lacrima/demo/crying.fap \
    /usr/share/lacrima/default-head.fdp.json /usr/share/applications/lacrima-player.desktop \
    /usr/share/applications/lacrima-editor.desktop /usr/share/mime/packages/lacrima.xml \
    /usr/share/metainfo/io.github.lacrima.player.metainfo.xml \
    /usr/share/icons/hicolor/scalable/apps/lacrima-editor.svg \
    /usr/share/icons/hicolor/256x256/apps/lacrima-player.png \
    /usr/share/man/man1/lacrima-fap.1.gz /usr/share/man/man1/lacrima-player.1.gz \
    /usr/share/man/man1/lacrima-send.1.gz /usr/share/man/man1/lacrima-batch.1.gz /usr/share/lacrima/livelink-mapping.json \
    /usr/share/man/man1/lacrima-editor.1.gz /usr/share/man/man1/lacrima-rig.1.gz \
    /usr/share/man/man1/lacrima-fetch-head.1.gz /usr/share/doc/lacrima/copyright \
    /usr/share/doc/lacrima/changelog.gz; do
  grep -qx "$path" <<<"$contents" || fail "the package lacks $path"
done
if grep -v '^/usr/' <<<"$contents" | grep -qv '^/$'; then
  fail "the package installs outside /usr: $(grep -v '^/usr/' <<<"$contents" | grep -v '^/$')"
fi
echo "contents: $(grep -c '[^/]$' <<<"$contents") files, all under /usr"

start=$SECONDS
# Every tag, down to pedantic ones, shown; only errors fail (lintian's exit 1), a lintian that
# cannot run (exit 2) too.
rc=0
lintian --display-info --pedantic --fail-on error "$deb" >"$out/lintian.txt" 2>&1 || rc=$?
[ "$rc" -le 1 ] || fail "lintian could not run (exit $rc): $(cat "$out/lintian.txt")"
echo "lintian ($((SECONDS - start)) s):"
sed 's/^/  /' "$out/lintian.txt"
grep -q '^E: ' "$out/lintian.txt" && fail "lintian reports errors"
allowed=$(sed -e 's/#.*//' -e '/^[[:space:]]*$/d' "$here/../lintian-warnings.txt" | awk '{print $1}')
while read -r tag; do
  grep -qx "$tag" <<<"$allowed" ||
    fail "lintian warning $tag is not in packaging/lintian-warnings.txt (fix it, or list it with its reason)"
done < <(sed -n 's/^W: [^ ]*: \([^ ]*\).*/\1/p' "$out/lintian.txt" | sort -u)
echo "lintian: no errors; every warning is listed in packaging/lintian-warnings.txt"
