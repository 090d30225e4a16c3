#!/usr/bin/env bash
# Tuning a tuned file changes nothing: the second run keeps every light's setting (the
# current one stays unless beaten by more than one pixel of error) and writes the same bytes.
source "$(dirname "$0")/common.sh" "$@"

tune --scene "$work/closed.gltf" --budget-ms 100000 --out "$work/once.gltf"
cmp -s "$work/closed.gltf" "$work/once.gltf" && fail "the first run changed nothing (the test needs a change)"
tune --scene "$work/once.gltf" --budget-ms 100000 --out "$work/twice.gltf" --report "$work/twice.json"
cmp "$work/once.gltf" "$work/twice.gltf" || fail "tuning the tuned file changed it: $(diff "$work/once.gltf" "$work/twice.gltf" | head)"
json "$work/twice.json" "any(l['changed'] for l in r['lights'])" | grep -qx False || fail "the report says a light changed"
echo "ok: tuning the tuned file changes nothing"
