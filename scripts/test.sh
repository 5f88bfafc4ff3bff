#!/usr/bin/env bash
# Sets up, builds and runs every test (GoogleTest suites and benchmark smoke runs) with ctest, then
# the SIMD kernels' tests built for any AVX2 machine (scripts/portability.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh "$@"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900
bash scripts/portability.sh
