#!/usr/bin/env bash
# The quality evaluation: the library with its defaults on the procedural corpus (208
# shapes in 8 families x 10 degradations, tools/evaluation/shape_corpus.h) and on every real
# scan of ../shared/data that has an expectation in expected_topology.json (skipped with
# a message when the folder is absent), as it is and in 4 degraded copies
# (tools/evaluation/scan_variants.h). Writes benchmark/QUALITY.md with the previous
# run's figures beside the new ones (from the committed benchmark/quality_results.tsv,
# which it then replaces), the scans' contact sheet benchmark/quality_scans.jpg, and the
# previews of every failed case under build-quality/quality/ (not committed).
#
#   scripts/quality.sh                 # everything, about 6 min on 2 cores
#   scripts/quality.sh --quick         # 3 shapes per family and the scans: a first look, no files replaced
#   scripts/quality.sh --no-build ...  # reuse build-quality
#   scripts/quality.sh -- --families trees --degradations clean,noise_1.0   # any df_l1_quality options (no files replaced)
#   scripts/quality.sh -- --families trees --resolution 150                 # another voxel_resolution than the default 100
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-quality"
out="$build/quality"
build_it=1
quick=0
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --no-build) build_it=0 ;;
    --quick) quick=1 ;;
    --build-dir) build="$2"; out="$build/quality"; shift ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,15p' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) echo "quality.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

if [ $build_it -eq 1 ]; then
  "$root/scripts/install_dependencies.sh" imagemagick
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDF_L1_BUILD_TESTS=OFF -DDF_L1_BUILD_EXAMPLES=OFF \
        -DDF_L1_BUILD_DOC=OFF -DDF_L1_BUILD_QUALITY=ON >/dev/null
  cmake --build "$build" --target df_l1_quality -j2
fi

scans="$root/../shared/data"
if [ ! -f "$scans/expected_topology.json" ]; then
  echo "quality.sh: no real scans ($scans/expected_topology.json absent): skipped" >&2
  scans=none
fi
rm -rf "$out"
mkdir -p "$out"
label="$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
if ! git -C "$root" diff --quiet HEAD 2>/dev/null; then label="$label + uncommitted changes"; fi

args=(--out "$out" --scans "$scans" --jobs 2 --quiet --label "$label ($(date -u +%Y-%m-%d))")
final=1
if [ $quick -eq 1 ]; then
  args+=(--shapes 3)
  final=0
fi
if [ ${#extra[@]} -gt 0 ]; then
  final=0
fi
if [ $final -eq 1 ]; then
  args+=(--previous "$root/benchmark/quality_results.tsv" --results "$out/results.tsv" --markdown "$out/QUALITY.md"
         --scan-sheet quality_scans.jpg --failure-sheet "build-quality/quality/failures_FAMILY.png")
else
  args+=(--previous "$root/benchmark/quality_results.tsv" --results "$out/results.tsv" --markdown "$out/QUALITY.md")
fi
"$build/bin/df_l1_quality" "${args[@]}" "${extra[@]}"

# Previews: SVG -> PNG for the scans and for up to 12 failures per family (the SVGs of
# all failures stay in $out/previews), and contact sheets (montage, from imagemagick).
render() { # sheet svg...
  local sheet="$1" files=()
  shift
  for svg in "$@"; do
    rsvg-convert -w 900 "$svg" -o "${svg%.svg}.png" && files+=("${svg%.svg}.png")
  done
  if [ ${#files[@]} -gt 0 ] && command -v montage >/dev/null; then
    montage "${files[@]}" -tile 4x -geometry 450x+4+4 "$sheet"
  fi
}
if command -v rsvg-convert >/dev/null; then
  shopt -s nullglob
  render "$out/scans.png" "$out"/scans/*.svg
  for family in thick_limbs tapering wavy trees loops sheets close_parts disjoint scan; do
    failed=("$out"/previews/"$family"_*.svg)
    if [ ${#failed[@]} -gt 0 ]; then render "$out/failures_$family.png" "${failed[@]:0:12}"; fi
  done
  shopt -u nullglob
fi

if [ $final -eq 1 ]; then
  cp "$out/results.tsv" "$root/benchmark/quality_results.tsv"
  cp "$out/QUALITY.md" "$root/benchmark/QUALITY.md"
  if [ -f "$out/scans.png" ]; then
    if command -v convert >/dev/null; then
      convert "$out/scans.png" -resize 2000x -quality 80 "$root/benchmark/quality_scans.jpg"
    fi
  fi
  echo "wrote benchmark/QUALITY.md, benchmark/quality_results.tsv; failure previews in $out/previews"
else
  echo "report of this partial run: $out/QUALITY.md (nothing in benchmark/ replaced)"
fi
