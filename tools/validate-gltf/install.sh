#!/usr/bin/env bash
# install.sh: refreshes vendor/node_modules/gltf-validator, the Khronos glTF-Validator as
# published on npm, at the version package-lock.json pins, checked against its sha512.
# A maintainer's tool, run when the pin changes; builds and tests never fetch anything:
# the package is one JavaScript file with no dependencies (Apache-2.0, vendor/.../LICENSE),
# and a fresh machine behind a proxy it does not trust cannot reach the registry.
# Needs node and npm and the npm registry.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
version=$(node -p "require('$here/package-lock.json').packages['node_modules/gltf-validator'].version")
integrity=$(node -p "require('$here/package-lock.json').packages['node_modules/gltf-validator'].integrity")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$work" && npm pack "gltf-validator@$version" --loglevel=error > /dev/null)
tarball=$work/gltf-validator-$version.tgz
actual="sha512-$(openssl dgst -sha512 -binary "$tarball" | base64 -w0)"
if [ "$actual" != "$integrity" ]; then
  echo "install.sh: gltf-validator $version has $actual, the lock file says $integrity" >&2
  exit 1
fi
target=$here/vendor/node_modules/gltf-validator
rm -rf "$target" && mkdir -p "$target"
tar -xzf "$tarball" -C "$target" --strip-components=1
echo "install.sh: vendored gltf-validator $version ($integrity)"
