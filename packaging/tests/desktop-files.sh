#!/usr/bin/env bash
# desktop-files.sh PACKAGING_SRC GENERATED WORK
#   The desktop entries, the AppStream metadata and the MIME types as they are installed,
#   through the freedesktop.org validators, and the MIME rules through shared-mime-info's own
#   database and a reader of it (the one xdg-mime uses outside a desktop session).
set -euo pipefail
src=$1 gen=$2 work=$3
. "$src/tests/lib.sh"
need desktop-file-validate:desktop-file-utils appstreamcli:appstream \
  update-mime-database:shared-mime-info mimetype:libfile-mimeinfo-perl

for app in player editor; do
  out=$(desktop-file-validate "$src/desktop/lacrima-$app.desktop" 2>&1) ||
    fail "desktop-file-validate lacrima-$app.desktop: $out"
  [ -z "$out" ] || fail "desktop-file-validate lacrima-$app.desktop has remarks: $out"
done
echo "desktop-file-validate: lacrima-player.desktop and lacrima-editor.desktop pass"

# --no-net: the test must run where only Debian's and npm's registries are reachable, and the
# metadata names no address to check.
appstreamcli validate --no-net --pedantic "$gen"/io.github.lacrima.*.metainfo.xml ||
  fail "appstreamcli validate"

rm -rf "$work"
mkdir -p "$work/data/mime/packages" "$work/files"
cp "$src/desktop/lacrima.xml" "$work/data/mime/packages/"
XDG_DATA_DIRS="$work/data:/usr/share" update-mime-database "$work/data/mime" || fail "update-mime-database rejected lacrima.xml"
demo=$src/../media/demo
cp "$demo/crying.fap" "$work/files/crying.fap"
cp "$demo/crying.json" "$work/files/crying.lacrima"
cp "$demo/crying.fap" "$work/files/no-extension-fap"
cp "$demo/crying.json" "$work/files/no-extension-project"
expect() {
  local got
  got=$(XDG_DATA_HOME="$work/data" XDG_DATA_DIRS=/usr/share mimetype --brief "$work/files/$1")
  [ "$got" = "$2" ] || fail "$1 is typed $got, expected $2"
  echo "mimetype $1: $got"
}
expect crying.fap text/x-mpeg4-fap
expect crying.lacrima application/x-lacrima-project
expect no-extension-fap text/x-mpeg4-fap          # the magic: "2.1 " at the start
expect no-extension-project application/x-lacrima-project  # the magic: "lacrima-project"
rm -rf "$work"
