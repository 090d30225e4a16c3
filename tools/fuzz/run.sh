#!/usr/bin/env bash
# Bounded libFuzzer run of the glTF loader:  tools/fuzz/run.sh [SECONDS]  (default 60)
#   1. builds tools/fuzz/ with Debian's clang into build-fuzz/ (apart from the GCC builds),
#   2. replays every file in tests/data/fuzz-regressions/: each must load or end in
#      engine::InputError, so crashes found once stay fixed,
#   3. writes the seed corpus (content/scenes + make_seeds) and fuzzes for SECONDS seconds.
# Fails on any finding (crash, sanitizer report, leak, uncaught non-InputError exception,
# input slower than 2 s, allocation over 512 MB, RSS over 2 GB) and prints the reproducer.
# Env: FUZZ_BUILD_DIR (default build-fuzz), FUZZ_JOBS (parallel fuzzing processes, default
# nproc).
set -euo pipefail
cd "$(dirname "$0")/../.."
root=$PWD
seconds=${1:-60}
build=${FUZZ_BUILD_DIR:-build-fuzz}
jobs=${FUZZ_JOBS:-$(nproc)}
regressions=tests/data/fuzz-regressions
start=$(date +%s)

# --- 1. build -------------------------------------------------------------------------
mkdir -p "$build"
cmake -S tools/fuzz -B "$build" -DCMAKE_CXX_COMPILER=clang++ > "$build/configure.log" 2>&1 \
  || { cat "$build/configure.log"; exit 1; }
cmake --build "$build" -j"$(nproc)"
build_done=$(date +%s)
echo "fuzz: build took $((build_done - start)) s"

fuzzer=$root/$build/gltf_fuzzer
limits=(-timeout=2 -rss_limit_mb=2048 -malloc_limit_mb=512)
# The harness's scene folders live here; a crashing run leaves its folder behind.
export TMPDIR=$root/$build/tmp
rm -rf "$TMPDIR" && mkdir -p "$TMPDIR"
# intercept_tls_get_addr=0: see tools/test.sh (a sanitizer-runtime bug crashes the exit-time leak check).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:allocator_may_return_null=0:intercept_tls_get_addr=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

# --- 2. regressions -------------------------------------------------------------------
failed=0
if [ -d "$regressions" ]; then
  while IFS= read -r -d '' input; do
    if ! "$fuzzer" "${limits[@]}" "$input" > "$build/replay.log" 2>&1; then
      cat "$build/replay.log"
      echo "fuzz: REGRESSION: $input fails again (log above)"
      echo "fuzz: reproduce: GLTF_FUZZ_VERBOSE=1 $build/gltf_fuzzer ${limits[*]} $input"
      failed=1
    fi
  done < <(find "$regressions" -type f ! -name '*.md' -print0 | sort -z)
fi
if [ "$failed" -ne 0 ]; then exit 1; fi
echo "fuzz: $(find "$regressions" -type f ! -name '*.md' 2>/dev/null | wc -l) regression inputs replayed, all fine"

# --- 3. fuzz --------------------------------------------------------------------------
rm -rf "$build/seeds" "$build/artifacts"
mkdir -p "$build/corpus" "$build/artifacts"
"$build/make_seeds" "$build/seeds" content/scenes
# corpus/ (first) receives what the fuzzer finds; seeds/ is read only. -fork runs `jobs`
# fuzzing processes until the time is up or the first finding (fork mode ignores OOMs and
# timeouts unless told otherwise).
set +e
"$fuzzer" "${limits[@]}" -max_total_time="$seconds" -fork="$jobs" -ignore_ooms=0 -ignore_timeouts=0 -ignore_crashes=0 \
  -dict=tools/fuzz/gltf.dict -artifact_prefix="$root/$build/artifacts/" -print_final_stats=1 \
  "$build/corpus" "$build/seeds" > "$build/fuzz.log" 2>&1
status=$?
set -e
findings=$(find "$build/artifacts" -type f | sort)
if [ "$status" -ne 0 ] || [ -n "$findings" ]; then
  # The sanitizer's report and the stack are in the log of the process that found it.
  grep -v -E '^(#[0-9]+|INFO:|MERGE|\s*$)' "$build/fuzz.log" | tail -n 80 || true
  echo "fuzz: FAILED (libFuzzer exit status $status); full log: $build/fuzz.log"
  for f in $findings; do
    echo "fuzz: reproducer: $f"
    echo "fuzz:   replay:   GLTF_FUZZ_VERBOSE=1 $build/gltf_fuzzer ${limits[*]} $f"
    echo "fuzz:   minimize: $build/gltf_fuzzer ${limits[*]} -minimize_crash=1 -runs=10000 $f"
    echo "fuzz:   then keep it: cp $f $regressions/<what-it-is>.<gltf|glb>"
  done
  exit 1
fi
rm -rf "$TMPDIR"
grep -E '^#[0-9]+: cov|stat::|Done' "$build/fuzz.log" | tail -n 3 || true
echo "fuzz: no findings in ${seconds} s of fuzzing ($(find "$build/corpus" -type f | wc -l) corpus inputs); total $(( $(date +%s) - start )) s"
