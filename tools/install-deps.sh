#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, only those missing.
# Safe to run repeatedly; needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config git
  libtinygltf-dev libglm-dev libglfw3-dev libepoxy-dev nlohmann-json3-dev libstb-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  libembree-dev libgtest-dev libgmock-dev libbenchmark-dev
  gnuplot-nox assimp-testmodels xvfb xauth
  # GNU parallel runs shadowmap-bench's shards side by side (docs/tuning.md, "Sharded sweeps").
  parallel
  # The scene generators (tools/scripts/*.py) and tools/engine-view/test/settings_round_trip.sh
  # run python3, which a minimal Debian 12 lacks.
  python3
  # tools/check-markdown.sh (CTest Readme.*) renders the README and docs/ with CommonMark's reference
  # implementation.
  cmark
  # glTF loader fuzzing (tools/fuzz/run.sh): clang, and libFuzzer's runtime
  # (libclang_rt.fuzzer-x86_64.a), which Debian 12 ships in libclang-rt-14-dev.
  clang libclang-rt-14-dev
  # glTF validation (tools/validate-gltf, CTest GltfValidate.*): node runs the Khronos
  # glTF-Validator, vendored in tools/validate-gltf/vendor (nothing is fetched from npm).
  nodejs
  # Compressed glTF: the loader decodes KHR_draco_mesh_compression with libdraco and
  # EXT_meshopt_compression with libmeshoptimizer (engine/src/gltf/Gltf*Decoder.cpp, also
  # linked by tools/fuzz); tests/unit/test_gltf_compressed.cpp and the shadow-mask test make
  # their meshopt files with gltfpack.
  libdraco-dev libmeshoptimizer-dev gltfpack
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
