#!/usr/bin/env bash
# The README's test command: sets up, builds and runs the test suite (GoogleTest suites, the
# programs' bad-input cases and benchmark smoke runs) but the long whole-sequence tests of
# tests/long_tests.txt, then the example built with default flags against this build's installed
# package (scripts/example.sh). CI then runs scripts/test_builds.sh: the long tests, the
# portable build's CPU variants and the sanitizer build with the fuzzers.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ctest_patterns.sh
bash scripts/build.sh "$@"
long=$(ctest_patterns tests/long_tests.txt build)
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900 -E "$long"
bash scripts/example.sh build  # this build's package, -march=native, used with default flags
