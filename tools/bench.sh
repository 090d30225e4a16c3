#!/usr/bin/env bash
# The default shadowmap-bench sweep: installs what is missing, builds, then times every
# shadow setting (variants x resolutions x depth formats x filters) against ray-traced
# truth on the showcase and Debian's 2CylinderEngine.glb, and the variants x resolutions
# (d24, pcf) on the alpha-masked scenes and their opaque twins (content/scenes/masked_*,
# opaque_*), into out/bench/ (results.csv, summary.md, time_vs_error.png). 540 rows: the
# 324 of them before the vsm and evsm filters took about 6 minutes on 2 cores (the masked
# scenes about 2 of those). Extra arguments go to shadowmap-bench (see
# build/bin/shadowmap-bench --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh build
mkdir -p out/bench
build/bin/shadowmap-bench --config content/engine.json --out out/bench "$@"
echo "wrote out/bench/results.csv, out/bench/summary.md, out/bench/time_vs_error.png"
