#!/usr/bin/env bash
# The batch on 2 local workers against the same files one after the other (doc/python.md).
#   python/benchmark/batch_speed.sh BUILD_DIR [N_CLOUDS] [POINTS]
# Generates N_CLOUDS (default 40) clouds of POINTS (default 20000) points with
# df_l1_generate (12 shapes x 4 variants, in turn), then times, on the same files:
#   1. the tool, one file after the other, all cores (its default)
#   2. the tool, one file after the other, --threads 1
#   3. python3 -m df_l1_skeleton.batch --workers 2 --threads 1 (with and without the cluster's start)
#   4. the same batch run again (every file skipped: the cost of resuming)
#   5. the batch on 1 worker of 1 thread (one file after the other, in the same engine)
set -euo pipefail
build="$(cd "$1" && pwd)"; n="${2:-40}"; points="${3:-20000}"
python="${PYTHON:-/usr/bin/python3}"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
shapes=(capsule y_junction star torus figure_eight theta stick_figure branching_tree helix many_armed dumbbell disjoint_pair)
variants=(clean noise outliers uneven)
mkdir -p "$work/clouds"
for ((i = 0; i < n; i++)); do
  "$build/bin/df_l1_generate" "${shapes[i % 12]}" "${variants[i / 12 % 4]}" "$points" "$i" \
    "$work/clouds/$(printf 'c%02d' "$i")_${shapes[i % 12]}.xyz" >/dev/null
done
seconds() { local start=$(date +%s.%N); "$@" >/dev/null; echo "$(date +%s.%N) - $start" | bc; }
batch() { "$python" -m df_l1_skeleton.batch "$work/clouds" "$work/batch" --workers 2 --threads 1 2>"$work/progress"; }
batch1() { "$python" -m df_l1_skeleton.batch "$work/clouds" "$work/batch1" --workers 1 --threads 1 2>"$work/progress1"; }
sequential() { # sequential OUT [tool options]
  local out="$1"; shift; mkdir -p "$out"
  for f in "$work"/clouds/*.xyz; do
    b="$(basename "$f" .xyz)"; "$build/bin/df_l1_skeleton" "$f" "$out/$b.obj" --report "$out/$b.json" --quiet "$@"
  done
}
t1=$(seconds sequential "$work/seq_all")
t2=$(seconds sequential "$work/seq_1" --threads 1)
export PYTHONPATH="$build/python"
t3=$(seconds batch)
# the batch's own last progress line: the seconds from the first task to the last, cluster start excluded
t3_tasks=$(tail -1 "$work/progress" | sed 's/.*), \([0-9.]*\) s (after.*/\1/')
t4=$(seconds batch)
t5=$(seconds batch1)
t5_tasks=$(tail -1 "$work/progress1" | sed 's/.*), \([0-9.]*\) s (after.*/\1/')
same=0
for f in "$work"/seq_1/*.obj; do cmp -s "$f" "$work/batch/$(basename "$f")" && same=$((same + 1)); done
printf '%d clouds of %d points (%s)\n' "$n" "$points" "$(nproc) cores, $(uptime | sed 's/.*load average: //') load"
printf 'tool, one after the other, all cores : %6.2f s\n' "$t1"
printf 'tool, one after the other, 1 thread  : %6.2f s\n' "$t2"
printf 'batch, 2 workers x 1 thread          : %6.2f s  (%.2fx the first, %.2fx the second)\n' "$t3" \
  "$(echo "$t1 / $t3" | bc -l)" "$(echo "$t2 / $t3" | bc -l)"
printf '  of which the tasks (cluster start excluded): %6.2f s  (%.2fx, %.2fx)\n' "$t3_tasks" \
  "$(echo "$t1 / $t3_tasks" | bc -l)" "$(echo "$t2 / $t3_tasks" | bc -l)"
printf 'batch again, every file skipped      : %6.2f s\n' "$t4"
printf 'batch, 1 worker x 1 thread (the same files one after the other in Dask): %6.2f s, tasks %6.2f s (2 workers: %.2fx, %.2fx)\n' \
  "$t5" "$t5_tasks" "$(echo "$t5 / $t3" | bc -l)" "$(echo "$t5_tasks / $t3_tasks" | bc -l)"
printf 'skeletons equal to the tool'"'"'s (--threads 1): %d of %d\n' "$same" "$n"
