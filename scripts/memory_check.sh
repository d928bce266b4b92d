#!/usr/bin/env bash
# The memory estimate against the measured peak: runs the tool on generated clouds
# (df_l1_generate, seed 7) at several sizes and voxel resolutions, and on the scans of
# ../shared/data when present, one process each, and prints a Markdown table of the
# tool's peak resident memory and its estimates (--report: peak_memory_mib; the
# constructor's initial_estimated_peak_memory_mib and the refined
# estimated_peak_memory_mib). Exit status 1 when the refined estimate is off by more
# than 25 %.
#
#   scripts/memory_check.sh [--build-dir DIR] [--large]    --large adds 3M and 10M points
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
large=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift ;;
    --large) large=1 ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "memory_check.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
tool="$build/bin/df_l1_skeleton"
generate="$build/bin/df_l1_generate"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cases=() # "file resolution"
sizes=(35000 300000 1000000)
[ "$large" = 1 ] && sizes+=(3000000 10000000)
for n in "${sizes[@]}"; do
  "$generate" stick_figure noise "$n" 7 "$work/stick_figure_$n.xyz" >/dev/null
  cases+=("$work/stick_figure_$n.xyz 100")
done
"$generate" branching_tree clean 35000 7 "$work/branching_tree.xyz" >/dev/null
for v in 50 200 300 400; do cases+=("$work/stick_figure_35000.xyz $v"); done
cases+=("$work/branching_tree.xyz 100" "$work/branching_tree.xyz 300")
shared="${DF_L1_SHARED_DATA_DIR:-$root/../shared/data}"
if [ -d "$shared" ]; then
  for f in "$shared"/*.off "$shared"/*.ply "$shared"/*.xyz; do [ -f "$f" ] && cases+=("$f 100"); done
else
  echo "memory_check: the shared data folder $shared is absent; generated clouds only" >&2
fi
echo "| input | points | voxel_resolution | measured peak MiB | initial estimate MiB | initial / peak | refined estimate MiB | refined / peak |"
echo "|---|---|---|---|---|---|---|---|"
status=0
for c in "${cases[@]}"; do
  set -- $c
  if ! "$tool" "$1" "$work/out.ply" --voxel-resolution "$2" --report "$work/r.json" --quiet 2>"$work/err"; then
    echo "| $(basename "$1") | | $2 | refused: $(tr -d '\n' <"$work/err" | cut -c1-80) | | | | |"
    continue
  fi
  line="$(python3 - "$work/r.json" "$(basename "$1")" "$2" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
peak, estimate = r["peak_memory_mib"], r["estimated_peak_memory_mib"]
initial = r.get("initial_estimated_peak_memory_mib", estimate)
ratio = estimate / peak
print(f"| {sys.argv[2]} | {r['counts']['input_points']} | {sys.argv[3]} | {peak:.0f} | {initial:.0f} | {initial / peak:.2f} "
      f"| {estimate:.0f} | {ratio:.2f}{'' if 0.75 <= ratio <= 1.25 else ' **off**'} |")
PY
)"
  echo "$line"
  case "$line" in *"**off**"*) status=1 ;; esac
done
exit $status
