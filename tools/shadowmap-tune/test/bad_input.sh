#!/usr/bin/env bash
# Bad input: one clear line on stderr, a non-zero exit, no file written.
source "$(dirname "$0")/common.sh" "$@"

expect_refusal() {  # expect_refusal PATTERN ARGS...: fails unless the run refuses as described
  local pattern=$1
  shift
  rm -f "$work/out.gltf"
  if tune "$@" --out "$work/out.gltf" > "$work/stdout" 2> "$work/stderr"; then fail "accepted: $*"; fi
  grep -q -- "$pattern" "$work/stderr" || fail "no \"$pattern\" in: $(cat "$work/stderr")"
  [[ $(grep -c . "$work/stderr") -eq 1 ]] || fail "not one line: $(cat "$work/stderr")"
  [[ ! -e $work/out.gltf ]] || fail "wrote a file for: $*"
}

expect_refusal 'light "spot": no setting fits --budget-ms 0.0001 (the fastest measured, .* takes .* ms); no file written' \
  --scene "$work/closed.gltf" --budget-ms 0.0001
expect_refusal 'no setting reaches --max-error 1e-09' --scene "$work/zero_offset.gltf" --variants standard \
  --resolutions 512 --max-error 0.000000001
expect_refusal '--views: unknown view spec "spin:3" (cameras or orbit:N)' --scene "$work/closed.gltf" --budget-ms 10 --views spin:3
expect_refusal 'dark.gltf: the scene has no lights: nothing to tune (add one with --key-light)' --scene "$work/dark.gltf" --budget-ms 10
expect_refusal 'give --budget-ms B or --max-error E' --scene "$work/closed.gltf"
expect_refusal "--key-light and --shard exclude each other: the key light is the scene's only light" \
  --scene "$work/dark.gltf" --budget-ms 10 --key-light spot --shard 1/2
expect_refusal '--key-light: ' --scene "$work/dark.gltf" --budget-ms 10 --key-light sun
echo "ok: bad input refused"
