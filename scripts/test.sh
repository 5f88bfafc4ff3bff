#!/usr/bin/env bash
# Sets up, builds and runs every test (GoogleTest suites and benchmark smoke runs) with ctest; then
# the example built with default flags against this build's installed package (scripts/example.sh),
# the portable build: its kernel tests on each CPU variant and the example against it
# (scripts/portable.sh), and the sanitizer build: every test again under ASan, UBSan and LSan, and
# the fuzzers from their seeds (scripts/sanitize.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh "$@"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900
bash scripts/example.sh build  # this build's package, -march=native, used with default flags
bash scripts/portable.sh
bash scripts/sanitize.sh
