#!/usr/bin/env bash
# Installs what is missing, builds in Release and runs the tool on the bundled input.
# Extra arguments go to the tool, e.g. scripts/run.sh my_scan.ply out.obj
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build"
"$root/scripts/install_dependencies.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DDF_L1_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" --target df_l1_skeleton -j2
mkdir -p "$build/out"
if [ $# -eq 0 ]; then
  set -- "$root/data/default_input.xyz" "$build/out/skeleton.obj" \
         --preview "$build/out/preview.svg" --report "$build/out/report.json"
fi
"$build/bin/df_l1_skeleton" "$@"
if [ -f "$build/out/skeleton.obj" ]; then
  echo "skeleton: $build/out/skeleton.obj"
  echo "preview:  $build/out/preview.svg"
  echo "report:   $build/out/report.json"
fi
