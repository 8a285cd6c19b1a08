#!/usr/bin/env bash
# fetch-gltf-validator.sh DIR
#   Installs the Khronos glTF Validator (npm gltf-validator, pinned below) into DIR/node_modules,
#   for the tests that prove Lacrima's .glb files against it (tests/export). Idempotent: with the
#   pinned version in place it does nothing, prints nothing and needs no network. Needs npm
#   (Debian's, or a Node.js from elsewhere); the validator is plain JavaScript, run by node.
set -euo pipefail

dir=${1:?usage: fetch-gltf-validator.sh DIR}
version=2.0.0-dev.3.10
# `npm view gltf-validator@2.0.0-dev.3.10 dist.integrity`: a different tarball must never be used.
integrity='sha512-odJ4k0tRkGXiDGn78yDBg+fBbAIvBnXxh3RwAta0emSxGtyagFE8B4xELB1oYe3S5RD8Ci3uZAsZaascH2LAEQ=='
package=$dir/node_modules/gltf-validator/package.json

if [ -f "$package" ] && grep -q "\"version\": \"$version\"" "$package"; then
  exit 0
fi
command -v npm >/dev/null || {
  echo "fetch-gltf-validator: npm is not installed (apt-get install npm)" >&2
  exit 1
}
mkdir -p "$dir"
npm install --prefix "$dir" --no-save --no-audit --no-fund --loglevel=error \
  "gltf-validator@$version" >&2
# npm verified the tarball against the registry's integrity; this checks that it is the pinned one.
found=$(node -e "const l = require(process.argv[1]);
  console.log((l.packages['node_modules/gltf-validator'] || {}).integrity || '')" \
  "$(realpath "$dir")/node_modules/.package-lock.json" 2>/dev/null || true)
if [ "$found" != "$integrity" ]; then
  rm -rf "$dir/node_modules/gltf-validator"
  echo "fetch-gltf-validator: the tarball's integrity $found is not the pinned $integrity" >&2
  exit 1
fi
[ -f "$package" ] || {
  echo "fetch-gltf-validator: npm did not install gltf-validator@$version into $dir" >&2
  exit 1
}
