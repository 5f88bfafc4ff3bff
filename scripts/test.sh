#!/usr/bin/env bash
# Sets up, builds and runs every test (GoogleTest suites and benchmark smoke runs) with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh "$@"
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900
