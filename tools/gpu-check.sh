#!/usr/bin/env bash
# The GPU check: the test suite and a frame-time table on a GPU's EGL device, in one report.
#
#   tools/gpu-check.sh [--table-only] [--frames N] [--size WxH] [--build DIR] REPORT_DIR
#       on a machine that can build (tools/install-deps.sh) and has a GPU driver: builds
#       build/ if it is missing, then checks.
#   tools/gpu-check.sh --bundle BUNDLE.tar.gz
#       on the build machine, after tools/build.sh: packs what a bare GPU machine (no compiler,
#       no network) needs: the build tree without its objects, the shared libraries its
#       programs load, the GL/EGL loader packages, the assimp test models and the outdoor scene.
#   tools/gpu-check.sh [--table-only] [--frames N] [--size WxH] --from BUNDLE.tar.gz REPORT_DIR
#       on the GPU machine, in a copy of this checkout: unpacks the bundle and checks.
#
# The device: ENGINE_EGL_DEVICE if set (docs/gpu.md), else the first EGL device that is not
# Mesa's software one, else the default display; rendering in software is an error. The report (REPORT_DIR/report.md) names
# the GL renderer, the tests that failed, and per scene x motion (still, orbiting light,
# orbiting camera) x llvmpipe switches (forced on; forced off: shade_cache, light_footprints
# and unrolled_light_sum forced false) the median, p99 and max frame time at WxH (default
# 1280x720), with every shader cache off (a first run's compiles show in the max).
# --table-only skips the tests; --build names the build tree (default build/).
# The same table on llvmpipe, for comparison: ENGINE_EGL_DEVICE=0 tools/gpu-check.sh
# --table-only REPORT_DIR on a machine without a GPU.
set -eEuo pipefail
# A command that stops the check under set -e says which, instead of exiting silently.
trap 'echo "gpu-check: line $LINENO: \"$BASH_COMMAND\" exited with status $?" >&2' ERR
cd "$(dirname "$0")/.."
source_dir=$PWD
usage() { sed -n '2,/^set -e/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit "${1:-1}"; }

frames=60
width=1280 height=720
build=build
table_only=false
bundle_out='' bundle_in='' report=''
while [ $# -gt 0 ]; do
  case $1 in
    --bundle) bundle_out=${2:?--bundle needs a file}; shift 2 ;;
    --from) bundle_in=${2:?--from needs a file}; shift 2 ;;
    --frames) frames=${2:?--frames needs a count}; shift 2 ;;
    --size) [[ ${2:-} =~ ^([0-9]+)x([0-9]+)$ ]] || { echo "gpu-check: --size needs WxH, not '${2:-}'" >&2; exit 1; }
            width=${BASH_REMATCH[1]} height=${BASH_REMATCH[2]}; shift 2 ;;
    --build) build=${2:?--build needs a folder}; shift 2 ;;
    --table-only) table_only=true; shift ;;
    -h|--help) usage 0 ;;
    -*) echo "gpu-check: unknown option $1" >&2; usage ;;
    *) [ -z "$report" ] || { echo "gpu-check: one REPORT_DIR, not '$report' and '$1'" >&2; exit 1; }
       report=$1; shift ;;
  esac
done

assimp_models=/usr/share/assimp/models/glTF2
engine_glb=$assimp_models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
gl_packages=(libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
# Libraries the GPU machine has its own of: glibc's, the C++ runtime (newer there or the
# same), and the vendor-neutral GL dispatch, which must be the machine's so it finds the
# vendor's driver.
system_libs='^(libc|libm|libdl|libpthread|librt|libresolv|ld-linux-x86-64|libstdc\+\+|libgcc_s|libEGL|libGL|libGLX|libGLdispatch|libOpenGL|libGLESv2)\.so'

# ---- packing, on the build machine ------------------------------------------------------
make_bundle() {
  [ -x build/bin/engine-render ] || { echo "gpu-check: build first (tools/build.sh)" >&2; exit 1; }
  stage=$(mktemp -d)
  trap 'rm -rf "$stage"' EXIT
  mkdir -p "$stage/libs" "$stage/gl-debs" "$stage/scenes"
  echo "$source_dir" > "$stage/source-dir"
  git describe --always --dirty > "$stage/commit" 2>/dev/null || echo unknown > "$stage/commit"
  # The build tree as ctest needs it (test lists, programs, plugins, the static libraries the
  # install test stages), without objects.
  tar -cf "$stage/build.tar" --exclude='*.o' --exclude='*.dir' build
  find build -type f \( -perm -u+x -o -name '*.so*' \) ! -path '*/CMakeFiles/*' -print0 |
    xargs -0 ldd 2>/dev/null | sed -n 's/^[[:space:]]*\([^ ]*\) => \(\/[^ ]*\) .*/\1 \2/p' | sort -u |
    while read -r name path; do
      [[ $name =~ $system_libs ]] || [[ $path == "$source_dir"/* ]] || cp -L "$path" "$stage/libs/$name"
    done
  # apt's download user must be able to reach and write there.
  chmod 755 "$stage" && chmod 777 "$stage/gl-debs"
  (cd "$stage/gl-debs" && apt-get download "${gl_packages[@]}" > /dev/null)
  [ -d "$assimp_models" ] && tar -cf "$stage/assimp-glTF2.tar" -C / "${assimp_models#/}"
  python3 tools/scripts/make_outdoor.py "$stage/scenes" > /dev/null
  tar -czf "$bundle_out" -C "$stage" .
  echo "gpu-check: wrote $bundle_out ($(du -h "$bundle_out" | cut -f1)): libraries $(cd "$stage/libs" && echo *)"
}

# ---- unpacking, on the GPU machine ------------------------------------------------------
unpack_bundle() {
  local dir=$1
  mkdir -p "$dir"
  tar -xzf "$bundle_in" -C "$dir"
  tar -xf "$dir/build.tar"   # into this checkout: build/
  # The build tree names the source folder it was configured in (test lists, rpaths, data).
  local built_in
  built_in=$(cat "$dir/source-dir")
  if [ "$built_in" != "$source_dir" ]; then
    if [ -e "$built_in" ]; then
      [ "$(cd "$built_in" && pwd -P)" = "$(pwd -P)" ] ||
        { echo "gpu-check: the bundle was built in $built_in, which here is another folder" >&2; exit 1; }
    else
      if ! mkdir -p "$(dirname "$built_in")" || ! ln -s "$source_dir" "$built_in"; then
        echo "gpu-check: cannot link $built_in to $source_dir (the bundle's build tree needs it)" >&2
        exit 1
      fi
    fi
  fi
  export LD_LIBRARY_PATH="$dir/libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  # A machine without the GL dispatch libraries gets the packed ones, unpacked beside the
  # bundle (not over /).
  if ! ldconfig -p | grep -q 'libEGL\.so\.1 '; then
    for deb in "$dir"/gl-debs/*.deb; do dpkg-deb -x "$deb" "$dir/gl-root"; done
    export LD_LIBRARY_PATH="$dir/gl-root/usr/lib/x86_64-linux-gnu:$LD_LIBRARY_PATH"
  fi
  if [ ! -d "$assimp_models" ] && [ -f "$dir/assimp-glTF2.tar" ]; then tar -xf "$dir/assimp-glTF2.tar" -C /; fi
  scenes=$dir/scenes
  commit=$(cat "$dir/commit")
}

# A GPU driver installed outside the loader's search paths (a container's /usr/local/nvidia):
# its libraries on the library path and its EGL vendor file named to glvnd.
use_vendor_driver() {
  local root=/usr/local/nvidia lib vendor_files
  [ -d "$root" ] || return 0
  for lib in "$root/lib64" "$root/lib"; do
    if [ -d "$lib" ]; then export LD_LIBRARY_PATH="$lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"; fi
  done
  if [ -z "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]; then
    vendor_files=$(find "$root/share/glvnd/egl_vendor.d" -name '*.json' 2>/dev/null | paste -sd: || true)
    if [ -n "$vendor_files" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor_files; fi
  fi
}

# ---- the check ---------------------------------------------------------------------------
render=$build/bin/engine-render
# "median frame X ms, p99 Y ms, max Z ms (RENDERER)" -> "X Y Z"
frame_summary() { sed -n 's/.*median frame \([0-9.]*\) ms, p99 \([0-9.]*\) ms, max \([0-9.]*\) ms (.*/\1 \2 \3/p'; }

# ENGINE_EGL_DEVICE if set; else the first listed EGL device that is not Mesa's software one;
# else (a driver that lists no device, as NVIDIA's in a VM without /dev/dri) the default
# display, if the renderer it gives is not a software one.
choose_device() {
  local listing
  listing=$(ENGINE_EGL_DEVICE=list "$render" --scene content/scenes/showcase.gltf --out "$work/list.png" \
              --width 64 --height 64 2>&1 >/dev/null || true)
  echo "$listing" > "$report/egl-devices.txt"
  if [ -z "${ENGINE_EGL_DEVICE:-}" ]; then
    ENGINE_EGL_DEVICE=$(echo "$listing" | grep '^EGL device' | grep -v '\[software\]' | head -1 |
                          sed -n 's/^EGL device \([0-9]*\):.*/\1/p' || true)
  fi
  if [ -n "$ENGINE_EGL_DEVICE" ]; then export ENGINE_EGL_DEVICE; else unset ENGINE_EGL_DEVICE; fi
  "$render" --scene content/scenes/showcase.gltf --out "$work/first.png" --width 64 --height 64 --frames 2 \
    > "$work/first.txt"
  renderer=$(sed -n 's/.*median frame .* ms (\(.*\))$/\1/p' "$work/first.txt" | head -1)
  if [ -z "${ENGINE_EGL_DEVICE:-}" ] && [[ $renderer =~ llvmpipe|softpipe|[Ss]oftware ]]; then
    echo "gpu-check: no GPU: EGL lists no device but Mesa's software one, and the default display" \
         "renders on $renderer. What EGL lists:" >&2
    echo "$listing" >&2
    exit 1
  fi
}

# The default config with the three llvmpipe switches forced on, and forced off (left
# unset, a GPU would turn them off and a software rasterizer on: docs/gpu.md).
switch_configs() {
  python3 - content/engine.json "$work" <<'PY'
import json, sys
for state in ("on", "off"):
    config = json.load(open(sys.argv[1]))
    value = state == "on"
    config.setdefault("renderer", {}).update(shade_cache=value, light_footprints=value, unrolled_light_sum=value)
    json.dump(config, open("%s/engine-switches-%s.json" % (sys.argv[2], state), "w"), indent=1)
PY
}

table_row() {  # scene label, scene file, light to orbit, then extra engine-render args
  local label=$1 scene=$2 light=$3
  shift 3
  local motion config switches args
  for motion in still light camera; do
    case $motion in
      still) args=() ;;
      light) args=(--orbit-light "$light") ;;
      camera) args=(--orbit-camera) ;;
    esac
    for switches in none on off; do
      case $switches in
        none) [ "$motion" = light ] && continue; config=content/engine-unshadowed.json ;;
        on|off) config=$work/engine-switches-$switches.json ;;
      esac
      local line
      line=$("$render" --config "$config" --scene "$scene" --out "$work/frame.png" --width "$width" --height "$height" \
               --frames "$frames" "$@" "${args[@]}" 2>>"$report/table-errors.txt" | frame_summary || true)
      [ -n "$line" ] || line="failed failed failed"
      # shellcheck disable=SC2086
      printf '| %s | %s | %s | %s | %s | %s |\n' "$label" "$motion" \
        "$([ "$switches" = none ] && echo unshadowed || echo "$switches")" $line | tee -a "$report/table.md"
    done
  done
}

run_table() {
  switch_configs
  : > "$report/table.md"
  echo "| scene | motion | llvmpipe switches | median ms | p99 ms | max ms |" >> "$report/table.md"
  echo "|---|---|---|---|---|---|" >> "$report/table.md"
  table_row showcase content/scenes/showcase.gltf spot_light
  table_row lamps content/scenes/lamps.gltf lamp_0
  table_row outdoor "$scenes/outdoor.gltf" sun
  if [ -f "$engine_glb" ]; then table_row 2CylinderEngine "$engine_glb" key_light --key-light spot; fi
  # Accuracy on this device: each scene's still frame against ray-traced truth.
  : > "$report/truth.txt"
  truth_of content/scenes/showcase.gltf
  truth_of content/scenes/lamps.gltf
  truth_of "$scenes/outdoor.gltf"
  if [ -f "$engine_glb" ]; then truth_of "$engine_glb" --key-light spot; fi
}

truth_of() {  # scene, then extra engine-render args
  local scene=$1
  shift
  echo "## $(basename "$scene") $*" >> "$report/truth.txt"
  "$render" --scene "$scene" --out "$work/truth.png" --width "$width" --height "$height" --truth "$@" \
    >> "$report/truth.txt" 2>&1 || echo "(failed)" >> "$report/truth.txt"
}

# The suite through ctest; a machine without CMake runs the gtest programs (the scripted
# tests need ctest).
run_tests() {
  local status=0 limit=${GPU_CHECK_TEST_SECONDS:-600} program
  if command -v ctest > /dev/null; then
    (cd "$build" && timeout "$limit" ctest -j"$(nproc)" --timeout 300 --output-on-failure) \
      > "$report/ctest.log" 2>&1 || status=$?
    {
      grep -E 'tests passed|tests failed' "$report/ctest.log" || echo "ctest ended with status $status, no summary"
      sed -n '/The following tests FAILED/,$p' "$report/ctest.log"
    } > "$report/tests.txt"
    return
  fi
  echo "no ctest here: the gtest programs alone" > "$report/tests.txt"
  for program in "$build"/bin/*_tests; do
    status=0
    timeout "$limit" "$program" --gtest_brief=1 >> "$report/ctest.log" 2>&1 || status=$?
    echo "$(basename "$program"): exit status $status" >> "$report/tests.txt"
  done
}

write_report() {
  {
    echo "# GPU check, $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo
    echo "- renderer: $renderer (ENGINE_EGL_DEVICE=${ENGINE_EGL_DEVICE:-unset: the default display})"
    echo "- CPU: $(nproc) cores, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)"
    echo "- commit: $commit"
    echo
    echo "## Tests"
    echo
    if $table_only; then echo "not run (--table-only)"; else echo '```'; cat "$report/tests.txt"; echo '```'; fi
    echo
    echo "## Frame time, ${width}x${height}, $frames frames, shader caches off"
    echo
    cat "$report/table.md"
    echo
    echo "## Against ray-traced truth"
    echo
    echo '```'
    # Each scene's heading and its per-light table.
    awk '/^## / { light = 0; print; next } /^  light +variant/ { light = 1 } light' "$report/truth.txt"
    echo '```'
  } > "$report/report.md"
}

if [ -n "$bundle_out" ]; then make_bundle; exit 0; fi
[ -n "$report" ] || usage
mkdir -p "$report"
report=$(cd "$report" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes=$work/scenes
commit=$(git describe --always --dirty 2>/dev/null || echo unknown)
if [ -n "$bundle_in" ]; then
  unpack_bundle "$work/bundle"
else
  [ -x "$render" ] || bash tools/build.sh "$build"
  mkdir -p "$scenes" && python3 tools/scripts/make_outdoor.py "$scenes" > /dev/null
fi
use_vendor_driver
# Every shader compiles as on a first run: Mesa's cache and NVIDIA's disk cache off.
export MESA_SHADER_CACHE_DISABLE=true __GL_SHADER_DISK_CACHE=0
missing=$(ldd "$render" "$build"/lib/libengine.so.0 | grep 'not found' || true)
[ -z "$missing" ] || { echo "gpu-check: libraries not found: $missing" >&2; exit 1; }
choose_device
echo "gpu-check: rendering on $renderer"
SECONDS=0
run_table
echo "gpu-check: frame table in $SECONDS s"
SECONDS=0
$table_only || { run_tests; echo "gpu-check: tests in $SECONDS s: $(head -1 "$report/tests.txt")"; }
write_report
echo "gpu-check: wrote $report/report.md"
