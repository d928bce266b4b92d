#!/usr/bin/env bash
# Checks the layout rules of include/ that the compiler does not see.
#
#   scripts/check_headers.sh            the include rules (a second; ctest runs this)
#   scripts/check_headers.sh --compile  also compiles every header alone, to show that
#                                       each one includes what it uses (about 90 s on 2 cores)
#
# The rules: a type header (Voxel_grid.h, Distance_field.h, ..., named with a capital,
# and errors.h) includes only type headers; an internal header includes only internal
# and type headers, never a stage function; no header of the package includes tools/,
# test/ or benchmark/. Exits 1 listing every break of a rule.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
compile=0
case "${1:-}" in
  --compile) compile=1 ;;
  "") ;;
  -h|--help) sed -n '2,11p' "$0"; exit 0 ;;
  *) echo "check_headers.sh: unknown option $1" >&2; exit 2 ;;
esac

cd "$root/include"
package=CGAL/DF_L1_skeleton
is_type_header() {
  local name="${1##*/}"
  [[ "$1" == "$package/$name" && ( "$name" =~ ^[A-Z] || "$name" == errors.h ) ]]
}

status=0
while IFS= read -r header; do
  while IFS= read -r included; do
    if [[ "$header" == */internal/* ]]; then
      if [[ "$included" != */internal/* ]] && ! is_type_header "$included"; then
        echo "$header: internal header includes the stage header $included"
        status=1
      fi
    elif is_type_header "$header" && ! is_type_header "$included"; then
      echo "$header: type header includes $included"
      status=1
    fi
  done < <(sed -n 's|^#include <\(CGAL/DF_L1_skeleton/[^>]*\)>.*|\1|p' "$header")
  if grep -nE '^#include ["<](tools|test|benchmark|evaluation)/' "$header"; then
    echo "$header: includes a file outside include/"
    status=1
  fi
done < <(find CGAL -name '*.h' | sort)

if [ "$compile" = 1 ]; then
  work="$(mktemp -d)"
  trap 'rm -rf "$work"' EXIT
  find CGAL -name '*.h' | sort > "$work/headers"
  compile_one() {
    local unit="$2/$(echo "$1" | tr / _).cpp"
    echo "#include <$1>" > "$unit"
    if ! g++ -std=c++17 -fsyntax-only -I. -I/usr/include/eigen3 "$unit" > "$unit.log" 2>&1; then
      echo "$1: does not compile alone:"
      head -5 "$unit.log"
      return 1
    fi
  }
  export -f compile_one
  xargs -P2 -I{} bash -c 'compile_one "$@"' _ {} "$work" < "$work/headers" || status=1
fi

[ "$status" = 0 ] && echo "check_headers.sh: $(find CGAL -name '*.h' | wc -l) headers follow the rules"
exit "$status"
