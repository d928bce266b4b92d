#!/usr/bin/env bash
# The whole test suite: everything built with the tests (build/), then ctest. With
# --hardened (what CI runs, .ci/run), two more steps:
#   2. the readers and the tool rebuilt with AddressSanitizer and UndefinedBehaviorSanitizer
#      (build-sanitize/) and their tests run again (df_l1_test_io, df_l1_test_tool, with
#      the scans of ../shared/data; the thread-count determinism test, 125 runs, only in
#      step 1);
#   3. a short fuzz run of each reader (scripts/fuzz.sh, clang, build-fuzz/).
# Ends with a summary of the steps; exit status 1 if any failed.
#
#   scripts/test.sh                 step 1
#   scripts/test.sh --hardened      the three steps
#   scripts/test.sh --sanitize      every test executable under ASan+UBSan (build-sanitize/)
#   options: --fuzz-seconds N (default 20 per reader)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mode=plain
fuzz_seconds=20
while [ $# -gt 0 ]; do
  case "$1" in
    --sanitize) mode=sanitize ;;
    --hardened) mode=ci ;;
    --fuzz-seconds) fuzz_seconds="$2"; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "test.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
if [ "$mode" = plain ]; then "$root/scripts/install_dependencies.sh"; else "$root/scripts/install_dependencies.sh" clang; fi
# A sanitizer report fails the test that triggers it, with a stack trace.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

sanitized_build() { # sanitized_build TARGET...
  # -O1 -g1: the sanitizers' checks and stack traces with file and line, in about 60 %
  # of the build time of -O2 -g
  cmake -S "$root" -B "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DDF_L1_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DDF_L1_BUILD_TESTS=ON -DDF_L1_BUILD_EXAMPLES=OFF -DDF_L1_BUILD_DOC=OFF >/dev/null
  cmake --build "$root/build-sanitize" -j2 ${1:+--target "$@"}
}

if [ "$mode" = sanitize ]; then
  sanitized_build
  cd "$root/build-sanitize"
  exec ctest --output-on-failure -j2 -E "df_l1_installed_package|df_l1_header_rules"
fi

status=()
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DDF_L1_BUILD_TESTS=ON >/dev/null
cmake --build "$root/build" -j2
if (cd "$root/build" && ctest --output-on-failure -j2); then status+=("tests: passed"); else status+=("tests: FAILED"); fi
# The Python module's pytest suite is ctest's df_l1_python when the module and pytest were found.
if (cd "$root/build" && ctest -N -R '^df_l1_python$' | grep -q 'Total Tests: 1'); then
  status+=("python: the module's pytest suite ran in the tests above (df_l1_python)")
else
  status+=("python: skipped, pybind11, numpy or pytest not found for $(sed -n "s/^Python3_EXECUTABLE:[A-Z]*=//p" "$root/build/CMakeCache.txt" | head -1) (Debian packages: scripts/install_dependencies.sh)")
fi
if [ "$mode" = ci ]; then
  start=$SECONDS
  bin="$root/build-sanitize/bin"
  if sanitized_build df_l1_skeleton df_l1_test_io df_l1_test_tool &&
     (cd "$root/build-sanitize" &&
      { "$bin/df_l1_test_io" --reporter compact & io=$!
        "$bin/df_l1_test_tool" --reporter compact "~[threads]~[.]"; tool=$?
        wait $io && [ $tool -eq 0 ]; }); then
    status+=("sanitized reader and tool tests (ASan+UBSan): passed in $((SECONDS - start)) s")
  else
    status+=("sanitized reader and tool tests (ASan+UBSan): FAILED")
  fi
  start=$SECONDS
  if "$root/scripts/fuzz.sh" "$fuzz_seconds"; then
    status+=("fuzzing, $fuzz_seconds s per reader: nothing found ($((SECONDS - start)) s)")
  else
    status+=("fuzzing, $fuzz_seconds s per reader: FAILED (findings in test/io/fuzz_regressions/)")
  fi
fi
printf '%s\n' "${status[@]}"
! printf '%s\n' "${status[@]}" | grep -q FAILED
