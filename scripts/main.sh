#!/usr/bin/env bash
# Sets up, builds and runs the main job. Until the surprise pipeline (novelty-run) lands, the main
# job prints what this build contains: build/bin/novelty-info.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
build/bin/novelty-info
echo "Programs built: $(cd build/bin && ls | tr '\n' ' ')" >&2
