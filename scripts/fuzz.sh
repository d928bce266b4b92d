#!/usr/bin/env bash
# Fuzzes the point cloud readers: builds the libFuzzer targets (fuzz/, clang with
# ASan and UBSan) in build-fuzz/, seeds a corpus per format, and runs each fuzzer
# for SECONDS (default 60). A crash, leak, sanitizer report, timeout or memory
# blow-up is copied to test/io/fuzz_regressions/<format>/, which df_l1_test_io
# replays; the exit status is then 1.
#
#   scripts/fuzz.sh [SECONDS] [FORMAT...]      FORMAT: xyz ply off (default: all)
#
# The corpus (build-fuzz/corpus/<format>) is kept between runs, so runs add up.
# Seeds are written here; the files of ../shared/data are added when the folder
# exists (never committed). DF_L1_FUZZ_JOBS=N runs N processes per fuzzer.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-60}"
shift || true
formats=("$@")
[ ${#formats[@]} -eq 0 ] && formats=(xyz ply off)
build="$root/build-fuzz"
shared="${DF_L1_SHARED_DATA_DIR:-$root/../shared/data}"
regressions="$root/test/io/fuzz_regressions"

cxx="${CXX:-clang++}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$cxx" \
  -DDF_L1_BUILD_FUZZERS=ON -DDF_L1_BUILD_TOOLS=OFF -DDF_L1_BUILD_TESTS=OFF \
  -DDF_L1_BUILD_EXAMPLES=OFF -DDF_L1_BUILD_DOC=OFF >/dev/null
cmake --build "$build" -j2 --target $(printf 'df_l1_fuzz_%s ' "${formats[@]}")

# --- Seeds: small valid and nearly valid files of each format ---------------
seed() { # seed FORMAT NAME CONTENT (printf format string)
  mkdir -p "$build/seeds/$1"
  printf "$3" >"$build/seeds/$1/$2"
}
seed xyz points '0 0 0\n1 2 3\n-1.5e3 2.25 +7\n'
seed xyz normals '0 0 0 0 0 1\n1 0 0 0 1 0\n'
seed xyz pts_count '2\n1 2 3\n4 5 6 # comment\n'
seed xyz crlf_bom '\xef\xbb\xbf# c\r\n1 2 3\r\n4\t5\t6\r\r7 8 9 1 2 3 4\n'
seed xyz odd '1e308 -1e-320 nan\ninf 0x1p3 1,5\n'
seed off plain 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n'
seed off noff 'NOFF 2 0 0\n0 0 0 0 0 1\n1 1 1 1 0 0\n'
seed off noff3 'NOFF\n2 0\n0 0 0\n1 1 1\n'
seed off cnoff '# c\nCNOFF\n1\n1 2 3 0 0 1 255 0 0\n'
seed off noff_dim 'nOFF 3\n1 0 0\n1 2 3\n'
seed off headerless '1.5 2 3\n4 5 6\n'
seed off headerless6 '1 2 3 0 0 1\n4 5 6 0 1 0\n'
seed off binary 'OFF BINARY\n1 0 0\n'
seed ply ascii 'ply\nformat ascii 1.0\ncomment c\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 0 0 1\n1 1 1 1 0 0\n3 0 1 0\n'
seed ply ascii_face_first 'ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 1\nproperty double z\nproperty uchar red\nproperty double x\nproperty double y\nend_header\n3 0 0 0\n1 255 2 3\n'
seed ply binary_le 'ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n\x00\x00\x80\x3f\x00\x00\x00\x40\x00\x00\x40\x40\x00\x00\x80\x3f\x00\x00\x00\x40\x00\x00\x40\x40'
seed ply binary_be 'ply\r\nformat binary_big_endian 1.0\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\nelement vertex 1\r\nproperty double x\r\nproperty double y\r\nproperty double z\r\nproperty short s\r\nend_header\r\n\x01\x00\x00\x00\x07\x3f\xf0\x00\x00\x00\x00\x00\x00\x40\x00\x00\x00\x00\x00\x00\x00\x40\x08\x00\x00\x00\x00\x00\x00\x00\x01'
seed ply binary_types 'ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty char x\nproperty uchar y\nproperty int16 z\nproperty uint16 nx\nproperty int ny\nproperty uint nz\nproperty list float uchar l\nend_header\n\xff\x01\x02\x00\x03\x00\x04\x00\x00\x00\x05\x00\x00\x00\x00\x00\x00\x40\x01\x02'

status=0
for format in "${formats[@]}"; do
  corpus="$build/corpus/$format"
  artifacts="$build/artifacts/$format"
  mkdir -p "$corpus" "$artifacts" "$build/logs"
  cp -n "$build/seeds/$format/"* "$corpus/"
  # The committed regressions are seeds too: a fixed bug stays covered.
  [ -d "$regressions/$format" ] && find "$regressions/$format" -type f ! -name '*.md' -exec cp -n {} "$corpus/" \;
  extra=()
  jobs=()
  [ "${DF_L1_FUZZ_JOBS:-1}" -gt 1 ] && jobs=(-jobs="$DF_L1_FUZZ_JOBS" -workers="$DF_L1_FUZZ_JOBS")
  if [ -d "$shared" ]; then
    case "$format" in
      xyz) pattern='\.(xyz|pts|txt)$' ;;
      *) pattern="\\.$format\$" ;;
    esac
    # Real scans (only their first max_len bytes matter); not copied into the corpus.
    shared_seeds="$build/shared_seeds/$format"
    mkdir -p "$shared_seeds"
    { find "$shared" -maxdepth 2 -type f | grep -Ei "$pattern" || true; } | while read -r f; do
      head -c 65536 "$f" >"$shared_seeds/$(basename "$f")"
    done
    extra=("$shared_seeds")
  fi
  echo "== fuzzing $format for $seconds s"
  log="$build/logs/$format-$(date -u +%Y%m%dT%H%M%S).log"
  before=$(find "$artifacts" -type f | wc -l)
  set +e
  # -max_len 64 KiB: room for long headers and many lines; a 10 s per-input
  # timeout catches hangs, and a 512 MB limit on one allocation (far more than
  # any 64 KiB input may cost) catches reservations that a header inflates.
  "$build/bin/df_l1_fuzz_$format" "$corpus" "${extra[@]}" \
    -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=512 "${jobs[@]}" \
    -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1
  rc=$?
  set -e
  grep -E '^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+ *DONE' "$log" || true
  after=$(find "$artifacts" -type f | wc -l)
  if [ "$rc" -ne 0 ] || [ "$after" -gt "$before" ]; then
    echo "!! $format: the fuzzer found something (exit $rc); see $log"
    mkdir -p "$regressions/$format"
    find "$artifacts" -type f -exec cp -n {} "$regressions/$format/" \;
    status=1
  fi
done
[ "$status" -eq 0 ] && echo "fuzz.sh: no findings"
exit "$status"
