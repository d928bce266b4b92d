#!/usr/bin/env bash
# Fingerprints of the skeletons the tool writes, to show that a change of structure
# leaves every result byte-identical.
#
#   scripts/skeleton_digests.sh                 print one line per input: name, sha256 of
#                                               the initial and of the final skeleton (.ply)
#                                               and of the final one's .polylines.txt
#   scripts/skeleton_digests.sh --check FILE    compare with a stored list (exit 1 on any
#                                               difference, listing it)
#   options: --build-dir DIR (default build; needs bin/df_l1_skeleton and bin/df_l1_generate),
#            --out FILE (write the list there instead of stdout)
#
# Inputs: the benchmark's headline clouds (35,000 points, seed 7), one generated corpus
# shape per family (clean and noise_0.6), and every scan of ../shared/data when present.
# The stored list is benchmark/skeleton_digests.tsv.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
check=""
out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift ;;
    --check) check="$2"; shift ;;
    --out) out="$2"; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "skeleton_digests.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
tool="$build/bin/df_l1_skeleton"
generate="$build/bin/df_l1_generate"
for program in "$tool" "$generate"; do
  [ -x "$program" ] || { echo "skeleton_digests.sh: $program is missing (build first)" >&2; exit 1; }
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

inputs=()
for case in stick_figure:clean torus:clean branching_tree:clean many_armed:clean stick_figure:noise; do
  file="$work/${case%%:*}-${case##*:}.xyz"
  "$generate" "${case%%:*}" "${case##*:}" 35000 7 "$file" >/dev/null
  inputs+=("$file")
done
index=0
for family in thick_limbs tapering wavy trees loops sheets close_parts disjoint; do
  for degradation in clean noise_0.6; do
    file="$work/${family}_$index-$degradation.xyz"
    "$generate" "${family}_$index" "$degradation" 20000 $((1000 + index)) "$file" >/dev/null
    inputs+=("$file")
  done
  index=$((index + 1))
done
data="$root/../shared/data"
if [ -d "$data" ]; then
  for file in "$data"/*.off "$data"/*.xyz "$data"/*.ply; do
    [ -f "$file" ] && inputs+=("$file")
  done
else
  echo "skeleton_digests.sh: $data not found, real scans skipped" >&2
fi

list="$work/digests.tsv"
: > "$list"
for file in "${inputs[@]}"; do
  name="$(basename "$file")"
  digest() {
    local out="$work/out.$1"
    shift
    if "$tool" "$file" "$out" --quiet --threads 2 "$@" 2>"$work/err"; then
      sha256sum "$out" | cut -c1-16
    else
      echo "error:$(head -c 60 "$work/err" | tr '\t\n' '  ')"
    fi
  }
  printf '%s\t%s\t%s\t%s\n' "$name" "$(digest ply --stage initial)" "$(digest ply)" \
    "$(digest polylines.txt)" >> "$list"
done

if [ -n "$check" ]; then
  # Inputs absent here (no ../shared/data) are left out of the comparison.
  cut -f1 "$list" | sort > "$work/names"
  awk -F'\t' 'NR == FNR { keep[$1] = 1; next } keep[$1]' "$work/names" "$check" | sort > "$work/stored"
  if diff "$work/stored" <(sort "$list") > "$work/diff"; then
    echo "skeleton_digests.sh: all $(wc -l < "$list") skeletons identical to $check"
  else
    echo "skeleton_digests.sh: skeletons differ from $check (< stored, > now):"
    cat "$work/diff"
    exit 1
  fi
elif [ -n "$out" ]; then
  cp "$list" "$out"
else
  cat "$list"
fi
