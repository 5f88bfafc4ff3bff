#!/usr/bin/env bash
# Installs the Debian packages (scripts/setup.sh), configures and builds NoveltyMaps into build/.
# Extra arguments go to CMake's configure step, e.g. -DNOVELTY_SANITIZE=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
generator=()
[ -f build/CMakeCache.txt ] || generator=(-G Ninja)  # an existing tree keeps its generator
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build --parallel "$(nproc)"
