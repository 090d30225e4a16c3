#!/usr/bin/env bash
# Two shards merged equal a single run: the same rows in the same order with the same
# errors (errors are deterministic: the same settings render the same pixels); only the
# times (columns 7-8 and 32-33, wall clock) differ, and the merge keeps each shard's row,
# times included, exactly as the shard wrote it. The sweep has three light size steps per filter,
# so shard 1 runs two jobs in a row that differ only in the size step (pcf at steps 1 and
# 3): the merge must deal them back as two jobs, and keep the size and soft columns. Then a
# merge missing a shard is refused.
# Usage: check_shards_merge.sh BENCH_BINARY CONTENT_DIR
set -euo pipefail
source "$(dirname "$0")/results_columns.sh"
bench=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

sweep() {
  "$bench" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" \
    --variants standard --resolutions 256 --depth-formats d24 --filters pcf,pcss \
    --light-radii 0.05,0.1,0.15 --angular-diameters 0.02,0.04,0.06 \
    --width 64 --height 48 --frames 1 "$@" 2> /dev/null
}
sweep --out "$out/single"
sweep --shard 1/2 --out "$out/shard1"
sweep --shard 2/2 --out "$out/shard2"
[[ -s $out/shard1/shard.json && -s $out/shard2/shard.json ]] || { echo "no shard.json written"; exit 1; }
# Each shard ran half of the 6 jobs (2 filters x 3 size steps, 3 lights each).
for k in 1 2; do
  rows=$(tail -n +2 "$out/shard$k/results.csv" | wc -l)
  [[ $rows -eq 9 ]] || { echo "shard $k: expected 9 rows, got $rows"; exit 1; }
done
# Merged in either order of the folders.
"$bench" --merge "$out/shard2" --merge "$out/shard1" --out "$out/merged"
diff <(results_without_times "$out/single/results.csv") <(results_without_times "$out/merged/results.csv") \
  || { echo "the merged shards differ from the single run"; exit 1; }
# --merge reads every column back (the times too): its rows are the shards' rows.
diff <(tail -q -n +2 "$out/shard1/results.csv" "$out/shard2/results.csv" | sort) \
  <(tail -n +2 "$out/merged/results.csv" | sort) \
  || { echo "the merged rows are not the shards' rows (a column not read back?)"; exit 1; }
awk -F, 'NR > 1 && ($19 <= 0 || $23 == "") { print "a merged row without its size or soft error: " $0; bad = 1 }
         END { exit bad }' "$out/merged/results.csv"
[[ -s $out/merged/summary.md ]] || { echo "no merged summary.md"; exit 1; }

if "$bench" --merge "$out/shard1" --out "$out/bad" 2> "$out/bad.log"; then echo "merged an incomplete sweep"; exit 1; fi
grep -q 'shard 2/2 missing' "$out/bad.log" || { echo "unclear refusal: $(cat "$out/bad.log")"; exit 1; }
[[ ! -e $out/bad ]] || { echo "wrote output for an incomplete sweep"; exit 1; }
echo "ok: two shards merged equal the single run"
