#!/usr/bin/env bash
# SPDX-License-Identifier: MPL-2.0
# Copyright Contributors to the isovdb project.
# Fuzzes every harness of fuzz/ for MINUTES each (default 10), one after the other, in
# a sanitizer build (ASan + UBSan, libFuzzer): build-fuzz, configured here, or the
# existing build that ISOVDB_BUILD_DIR names (CI's build-asan has the harnesses too). Each harness starts from its seed corpus in
# fuzz/corpus/<name>/ and keeps what it finds new in OUT/corpus/<name>/; a finding
# (crash, sanitizer report, uncaught exception other than the library's input errors,
# leak, > 10 s per input, > 2 GB) is written to OUT/findings/<name>/ and listed at the
# end. Run on demand, never in CI:
#     bench/fuzz.sh [MINUTES] [OUT] [HARNESS...]
set -euo pipefail
cd "$(dirname "$0")/.."
minutes="${1:-10}"
out="${2:-fuzz-out}"
shift $(( $# > 2 ? 2 : $# ))
build="${ISOVDB_BUILD_DIR:-build-fuzz}"
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(raw nrrd metaimage segy vdb grdecl ply obj stl glb gltf slice_image extract)
command -v clang++-14 >/dev/null || { echo "fuzz.sh: needs clang++-14 (apt-get install clang-14 libfuzzer-14-dev)" >&2; exit 2; }
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
    -DISOVDB_SANITIZE=ON -DISOVDB_BUILD_FUZZERS=ON -DISOVDB_BUILD_TESTS=OFF >/dev/null
elif ! grep -q '^ISOVDB_BUILD_FUZZERS:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "fuzz.sh: $build is not a fuzzing build (ISOVDB_BUILD_FUZZERS=OFF); name another with ISOVDB_BUILD_DIR" >&2
  exit 2
fi
cmake --build "$build" -j"$(nproc)" --target "${harnesses[@]/#/fuzz_}"
# The tests' sanitizer environment (cmake/IsovdbSanitizers.cmake): TBB's alignment reports
# suppressed, every other report fatal.
export UBSAN_OPTIONS="suppressions=$PWD/cmake/ubsan_suppressions.txt:halt_on_error=1:print_stacktrace=1"
found=0
for name in "${harnesses[@]}"; do
  mkdir -p "$out/corpus/$name" "$out/findings/$name"
  echo "fuzz.sh: $name for $minutes min" >&2
  status=0
  "$build/fuzz/fuzz_$name" -max_total_time=$((minutes * 60)) -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="$out/findings/$name/" -print_final_stats=1 \
    "$out/corpus/$name" "fuzz/corpus/$name" >"$out/$name.log" 2>&1 || status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$out/$name.log" | grep -o '[0-9]*$' || echo "?")
  if [ "$status" -ne 0 ]; then
    found=1
    echo "fuzz.sh: $name: FINDING after $runs runs (exit $status), see $out/$name.log and $out/findings/$name/" >&2
  else
    echo "fuzz.sh: $name: $runs runs, no finding" >&2
  fi
done
exit "$found"
