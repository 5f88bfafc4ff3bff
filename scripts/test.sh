#!/usr/bin/env bash
# Sets up, builds and runs every test (GoogleTest suites and benchmark smoke runs) with ctest; then
# the example built with default flags against this build's installed package (scripts/example.sh),
# the portable build: its kernel tests on each CPU variant and the example against it
# (scripts/portable.sh), and the sanitizer build: the tests again under ASan, UBSan and LSan but
# the whole-sequence ones of tests/sanitizer_skip.txt, and the fuzzers from their seeds
# (scripts/sanitize.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh "$@"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900
bash scripts/example.sh build  # this build's package, -march=native, used with default flags
bash scripts/portable.sh
bash scripts/sanitize.sh
