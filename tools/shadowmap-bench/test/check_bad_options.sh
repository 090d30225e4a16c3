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
  if [[ $status -ne 1 || $output != *"$fragment"* || $(wc -l <<< "$output") -ne 1 ]]; then
    echo "shadowmap-bench $*: expected exit 1 and \"$fragment\", got $status: $output"
    failed=1
  fi
}

expect_error '--resolutions: empty item in "512,,1024" (items are separated by single commas)' --resolutions 512,,1024
expect_error '--resolutions: "512" is listed twice in "512,512"' --resolutions 512,512
expect_error '--resolutions: "0" is not an integer in [1, ' --resolutions 0
expect_error '--width: "+64" is not an integer in [1, 16384]' --width +64
expect_error '--variants: unknown value "none" (known: standard,woo,backface,volume)' --variants none
expect_error '--filters: unknown value "bilinear" (known: nearest,pcf,pcss,vsm,evsm)' --filters bilinear
expect_error '--key-light: "sun" is not spot, point, directional or none' --key-light sun
expect_error '--time: "-1" is not a number in [0, 1000000]' --time -1
expect_error '--time: "0.5" is listed twice in "0.5,0.5"' --time 0.5,0.5
expect_error '--shimmer: "1" is not an integer in [2, 10000]' --shimmer 1
# The optional axes, bounded as the plugin bounds their keys (shadowmap::settingKey).
expect_error '--light-radii: "-0.1" is not a number in [0, inf]' --light-radii -0.1
expect_error '--angular-diameters: "-0.01" is not a number in [0, inf]' --angular-diameters 0.05,-0.01
expect_error '--filter-radii: "17" is not a number in [0, 16]' --filter-radii 17
expect_error '--filter-taps: "3" is not an integer in [4, 64]' --filter-taps 3
expect_error '--normal-offsets: "9" is not a number in [0, 8]' --normal-offsets 9
expect_error '--bleed-reductions: "1" is not a number in [0, 0.95]' --bleed-reductions 0.2,1
expect_error '--light-radii and --angular-diameters: 2 and 1 values' --light-radii 0.1,0.2 --angular-diameters 0.05
expect_error '--projections: unknown value "perspective" (known: uniform,lispsm)' --projections perspective
expect_error '--cascades: unknown value "5" (known: auto,1,2,3,4)' --cascades 1,5
expect_error '--cascades: "2" is listed twice in "2,2"' --cascades 2,2
expect_error '--stables: unknown value "yes" (known: true,false)' --stables yes
# Axes that would multiply no row.
expect_error '--stables: a lispsm warp is never stable' --projections lispsm --stables true,false
expect_error '--filter-radii: only pcf, vsm and evsm have a filter radius, and --filters lists none of them' \
  --filters nearest,pcss --filter-radii 2
expect_error '--filter-taps: only pcss and pcf with a --filter-radii value above 0 take taps' --filters pcf --filter-taps 8
# vsm's and evsm's blur radius is no pcf disk: it takes no taps.
expect_error '--filter-taps: only pcss and pcf with a --filter-radii value above 0 take taps' \
  --filters vsm,evsm --filter-radii 2 --filter-taps 8
expect_error '--bleed-reductions: only vsm and evsm have a bleed reduction, and --filters lists neither' \
  --filters nearest,pcf,pcss --bleed-reductions 0.2
[[ $failed -eq 0 ]] && echo "ok"
exit $failed
