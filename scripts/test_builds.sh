#!/usr/bin/env bash
# What CI runs after the README's test command (scripts/test.sh, whose build/ it reuses): the
# long whole-sequence tests of tests/long_tests.txt, the portable build's SIMD kernel tests on
# each CPU variant with the example against it (scripts/portable.sh), the kernels' tests built
# for aarch64 and run under qemu-user (scripts/cross_aarch64.sh), and the sanitizer build:
# the suite again under ASan, UBSan and LSan and the fuzzers from their seeds
# (scripts/sanitize.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ctest_patterns.sh
[ -f build/CMakeCache.txt ] || bash scripts/build.sh
cmake --build build --parallel "$(nproc)"
long=$(ctest_patterns tests/long_tests.txt build)
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900 -R "$long"
bash scripts/portable.sh
bash scripts/cross_aarch64.sh
bash scripts/sanitize.sh
