#!/usr/bin/env bash
# Builds the SIMD kernels and their tests for any AVX2 machine (-march=x86-64-v3, no
# -march=native) and runs them: the paths without AVX-512 are compiled and checked too. A second
# build tree beside build/; run after scripts/build.sh (the packages are installed there).
set -euo pipefail
cd "$(dirname "$0")/.."
tests=(normal_gamma_batch_test lanes_test with_count_test ycbcr_planes_test interleave_test
       fill_where_test row_windows_test planar_blocks_test mesh_plan_test depth_mesh_warper_test quad_rasteriser_test
       view_blender_test view_based_map_test)
cmake -S . -B build-x86-64-v3 -G Ninja -DCMAKE_BUILD_TYPE=Release -DNOVELTY_NATIVE=OFF \
  -DCMAKE_CXX_FLAGS=-march=x86-64-v3 > /dev/null
cmake --build build-x86-64-v3 --parallel "$(nproc)" --target "${tests[@]}"
for t in "${tests[@]}"; do
  echo "x86-64-v3: $t"
  build-x86-64-v3/bin/"$t" --gtest_brief=1
done
