#!/usr/bin/env bash
# install.sh DIR: installs the Khronos glTF-Validator at the version package-lock.json pins
# (name, version and sha512) into DIR/node_modules. `npm ci` installs exactly the lock file,
# never a newer release, so a validator update is a reviewed change of package-lock.json.
# Needs node and npm (tools/install-deps.sh) and the npm registry, or npm's cache.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
dir=${1:?usage: install.sh DIR}
mkdir -p "$dir"
cp "$here/package.json" "$here/package-lock.json" "$dir/"
npm ci --prefix "$dir" --no-audit --no-fund --ignore-scripts --loglevel=error
