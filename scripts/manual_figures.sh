#!/usr/bin/env bash
# Renders the manual's figures of the pipeline stages with our own tool: one
# `--preview-stages` run on the bundled input, cut into one PNG per row.
#
#   scripts/manual_figures.sh [--build-dir DIR]     writes doc/figures/stage_*.png
#
# Needs bin/df_l1_skeleton in the build directory (default build), python3 and
# rsvg-convert (librsvg2-bin).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "manual_figures.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
tool="$build/bin/df_l1_skeleton"
[ -x "$tool" ] || { echo "manual_figures.sh: $tool is missing (build first)" >&2; exit 1; }
command -v rsvg-convert >/dev/null || { echo "manual_figures.sh: rsvg-convert is missing (apt-get install librsvg2-bin)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

"$tool" "$root/data/default_input.xyz" "$work/skeleton.obj" --threads 2 --quiet \
  --preview "$work/stages.svg" --preview-stages

# Rows top to bottom: final skeleton, contracted samples, initial skeleton, distance
# field, voxels. Each row becomes an SVG of its band of the picture, without the
# picture's title (the manual names the input).
python3 - "$work/stages.svg" "$work" <<'EOF'
import re, sys
svg = open(sys.argv[1]).read()
width = float(re.search(r'<svg[^>]* width="([0-9.]+)"', svg).group(1))
tops = [float(y) - 15 for y in re.findall(r'class="row-title" x="[0-9.]+" y="([0-9.]+)"', svg)]
names = ["final", "contraction", "initial_skeleton", "distance_field", "voxels"]
if len(tops) != len(names):
    sys.exit("manual_figures.sh: expected %d rows, found %d" % (len(names), len(tops)))
height = tops[1] - tops[0]
for name, top in zip(names, tops):
    band = re.sub(r'(<svg[^>]*) height="[0-9.]+" viewBox="[^"]*"',
                  r'\1 height="%.1f" viewBox="0 %.1f %.1f %.1f"' % (height, top, width, height), svg, count=1)
    open("%s/stage_%s.svg" % (sys.argv[2], name), "w").write(band)
EOF

mkdir -p "$root/doc/figures"
for name in voxels distance_field initial_skeleton contraction final; do
  rsvg-convert -w 760 -b white "$work/stage_$name.svg" -o "$root/doc/figures/stage_$name.png"
done
echo "manual_figures.sh: wrote doc/figures/stage_{voxels,distance_field,initial_skeleton,contraction,final}.png"
