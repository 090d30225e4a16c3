# Sourced by the bench tests that read results.csv: its header as shadowmap-bench writes it
# (ResultsCsv), once for all of them, and the check that a file starts with it.
results_header='scene,light,variant,resolution,depth_format,filter,shadow_ms,frame_ms,acne,leak,error,error_noedge,area_acne,area_leak,area_error,shimmer,near_error,near_error_noedge,light_size,filter_radius,filter_taps,normal_offset,soft_error,soft_error_noedge,penumbra_error,texel_m_mean,texel_m_p95,projection,cascades,stable,bleed_reduction,frame_p99_ms,frame_max_ms'

# Exits with a message unless results file $1 starts with results_header.
check_results_header() {
  [[ "$(head -n 1 "$1")" == "$results_header" ]] || { echo "bad header: $(head -n 1 "$1")"; exit 1; }
}

# Exits with a message unless every row of results file $1 was measured: 33 fields, a positive
# shadow time, errors (columns 9-15) in [0, 100].
check_rows_measured() {
  awk -F, 'NR > 1 {
    if (NF != 33) { print NF " fields, expected 33: " $0; bad = 1 }
    if (!($7 > 0)) { print "no shadow time: " $0; bad = 1 }
    for (i = 9; i <= 15; ++i) if (!($i >= 0 && $i <= 100)) { print "error out of [0,100]: " $0; bad = 1 }
  } END { exit bad }' "$1" || exit 1
}

# Results file $1 without its timing columns, which differ from run to run: 7-8 (shadow_ms,
# frame_ms) and 32-33 (frame_p99_ms, frame_max_ms).
results_without_times() { cut -d, -f1-6,9-31 "$1"; }

# Runs the caller's sweep() as two shards into $2/shard1 and $2/shard2, merges them with
# shadowmap-bench $3 into $2/merged, and exits with a message unless the merge equals the
# single run's results file $1 but for the times.
check_shards_merge_to() {
  local single=$1 out=$2 bench=$3
  sweep --shard 1/2 --out "$out/shard1" 2> /dev/null
  sweep --shard 2/2 --out "$out/shard2" 2> /dev/null
  "$bench" --merge "$out/shard1" --merge "$out/shard2" --out "$out/merged" 2> /dev/null
  diff <(results_without_times "$single") <(results_without_times "$out/merged/results.csv") \
    || { echo "the merged shards differ from the single run"; exit 1; }
}
