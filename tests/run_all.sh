#!/usr/bin/env bash
# The whole test suite, after the README's main command has built ./build:
#   1. the unit, table and command-line tests of the Release build;
#   2. the same suite built with AddressSanitizer and UndefinedBehaviorSanitizer
#      (CMake preset `sanitize`, clang);
#   3. a bounded libFuzzer run on every table reader, built in the same
#      sanitizer tree (the first input byte picks the read options, see
#      fuzz_read_table.cpp), seeded from tests/fuzz/corpus: one worker per
#      job (libFuzzer's fork mode) for BRDFLUT_FUZZ_SECONDS of wall time
#      (default 30, so 60 seconds of fuzzing on 2 cores).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${BRDFLUT_JOBS:-2}
log=$(mktemp -d)
trap 'rm -rf "$log"' EXIT

lap() {  # seconds since the previous lap (wall clock), for the stage lines
    echo "   ($1: $((SECONDS - last)) s)"
    last=$SECONDS
}
last=$SECONDS

count() {  # "N tests passed" summary of a ctest log -> "passed failed"
    sed -n 's/.*tests passed, \([0-9]*\) tests failed out of \([0-9]*\).*/\1 \2/p' "$1" | tail -n 1
}

echo "== Release build: ctest"
ctest --test-dir build --output-on-failure -j"$jobs" | tee "$log/release.txt"
lap "Release ctest"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer (and the fuzzer): build and ctest"
cmake --preset sanitize > "$log/sanitize-configure.txt"
cmake --build --preset sanitize -j"$jobs" > "$log/sanitize-build.txt" || { tail -n 50 "$log/sanitize-build.txt"; exit 1; }
lap "sanitizer configure and build"
ctest --preset sanitize -j"$jobs" | tee "$log/sanitize.txt"
lap "sanitizer ctest"

echo "== libFuzzer on the table readers"
mkdir -p "$log/corpus"
./build-sanitize/fuzz_read_table -fork="$jobs" -ignore_crashes=0 -ignore_timeouts=0 -ignore_ooms=0 \
    -max_total_time="${BRDFLUT_FUZZ_SECONDS:-30}" -seed=1 -timeout=10 -rss_limit_mb=2048 \
    -max_len=65536 "$log/corpus" tests/fuzz/corpus > "$log/fuzz.txt" 2>&1 ||
    { tail -n 60 "$log/fuzz.txt"; exit 1; }
grep -E "^#[0-9]+: cov:" "$log/fuzz.txt" | tail -n 1 || true  # inputs run, coverage, crashes (0/0/0)
lap "fuzzing"

read -r rf rt <<< "$(count "$log/release.txt")"
read -r sf st <<< "$(count "$log/sanitize.txt")"
passed=$(( (rt - rf) + (st - sf) + 1 ))
failed=$(( rf + sf ))
echo "Release: $((rt - rf)) of $rt passed; sanitizers: $((st - sf)) of $st passed; fuzzing: no crash"
echo "tests: $passed passed, $failed failed"
