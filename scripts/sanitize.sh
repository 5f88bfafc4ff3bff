#!/usr/bin/env bash
# The sanitizer build (build-sanitize/, clang): AddressSanitizer, UndefinedBehaviorSanitizer and
# LeakSanitizer over the test suite but the whole-sequence tests of tests/sanitizer_skip.txt, the
# libFuzzer targets of tests/fuzz among them (each runs NOVELTY_FUZZ_RUNS inputs from its seeds).
# Clang, because libFuzzer is clang's; our code builds with both compilers (core/lanes.h). Run
# after scripts/build.sh (packages installed there).
#   scripts/sanitize.sh [--fuzz-runs N]     (default 3000; 1000000 for a real fuzzing session)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=3000
if [ "${1:-}" = "--fuzz-runs" ]; then runs=$2; fi
generator=()
[ -f build-sanitize/CMakeCache.txt ] || generator=(-G Ninja)
CC=clang CXX=clang++ cmake -S . -B build-sanitize "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DNOVELTY_SANITIZE=ON -DNOVELTY_FUZZ=ON -DNOVELTY_WERROR=OFF -DNOVELTY_FUZZ_RUNS="$runs" > /dev/null
cmake --build build-sanitize --parallel "$(nproc)"
# Every finding fails its test: UBSan aborts (-fno-sanitize-recover), ASan and LSan exit non-zero.
# Leaks inside third-party libraries' process-lifetime caches are listed in tests/lsan.supp.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The tests listed in tests/sanitizer_skip.txt (whole sequences, 30 s to 5 min each under the
# sanitizers) run in the plain build only. A line that names no test is an error: a renamed test
# would otherwise run here again, unnoticed, and the stage outgrow CI's time.
source scripts/ctest_patterns.sh
skip=$(ctest_patterns tests/sanitizer_skip.txt build-sanitize)
ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" --timeout 1800 \
  --no-tests=error -E "$skip"
