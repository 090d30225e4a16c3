# Sourced by the bench tests that read results.csv: its header as shadowmap-bench writes it
# (ResultsCsv), once for all of them, and the check that a file starts with it.
results_header='scene,light,variant,resolution,depth_format,filter,shadow_ms,frame_ms,acne,leak,error,error_noedge,area_acne,area_leak,area_error,shimmer,near_error,near_error_noedge,light_size,filter_radius,filter_taps,normal_offset,soft_error,soft_error_noedge,penumbra_error,texel_m_mean,texel_m_p95,projection,cascades,stable,bleed_reduction,frame_p99_ms,frame_max_ms'

# Exits with a message unless results file $1 starts with results_header.
check_results_header() {
  [[ "$(head -n 1 "$1")" == "$results_header" ]] || { echo "bad header: $(head -n 1 "$1")"; exit 1; }
}
