#!/usr/bin/env bash
# shadowmap-bench refuses bad option values with the command-line toolkit's messages
# (tools/common/OptionValues.h), as every tool words them: exit code 1 and one line naming
# the flag and the value, before any scene is loaded.
# Usage: check_bad_options.sh BENCH_BINARY
set -uo pipefail
bench=$1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failed=0

expect_error() {  # expect_error FRAGMENT ARGS...
  local fragment=$1
  shift
  local output status
  output=$("$bench" --out "$out" "$@" 2>&1)
  status=$?
  if [[ $status -ne 1 || $output != *"$fragment"* ]]; then
    echo "shadowmap-bench $*: expected exit 1 and \"$fragment\", got $status: $output"
    failed=1
  fi
}

expect_error '--resolutions: empty item in "512,,1024" (items are separated by single commas)' --resolutions 512,,1024
expect_error '--resolutions: "512" is listed twice in "512,512"' --resolutions 512,512
expect_error '--resolutions: "0" is not an integer in [1, ' --resolutions 0
expect_error '--width: "+64" is not an integer in [1, 16384]' --width +64
expect_error '--variants: unknown value "none" (known: standard,woo,backface)' --variants none
expect_error '--filters: unknown value "bilinear" (known: nearest,pcf,pcss)' --filters bilinear
expect_error '--key-light: "sun" is not spot, point, directional or none' --key-light sun
expect_error '--time: "-1" is not a number in [0, 1000000]' --time -1
expect_error '--time: "0.5" is listed twice in "0.5,0.5"' --time 0.5,0.5
expect_error '--shimmer: "1" is not an integer in [2, 10000]' --shimmer 1
[[ $failed -eq 0 ]] && echo "ok"
exit $failed
