#!/usr/bin/env bash
# The portable build (-DNOVELTY_PORTABLE=ON, build-portable/): libraries for any x86-64 with their
# AVX2 (x86-64-v3) and AVX-512 (x86-64-v4) variants in glibc-hwcaps/, chosen by the loader. Runs
# the SIMD kernels' tests on every variant this CPU can run (the loader is told to ignore the
# others: GLIBC_TUNABLES), the header-only kernels' tests built for x86-64-v3 (build-x86-64-v3/),
# then scripts/example.sh against this tree's installed package. Run
# after scripts/build.sh (the packages are installed there).
set -euo pipefail
cd "$(dirname "$0")/.."
# The SIMD kernels' suites, by test program (bin/<part>_tests) and GoogleTest filter.
kernels=(
  "core_tests Lanes.*:RowWindows.*:WithCount.*:Interleave.*:FillWhere.*"
  "maps_tests NormalGammaBatch.*:NormalGammaPackets.*:YCbCrPlanes.*:PlanarBlocks.*:MeshPlan.*:DepthMeshWarper.*:QuadRasteriser.*:ViewBlender.*:ViewBasedMap.*"
  "mrpt_plugins_tests CAppearanceMap.*")
programs=()
for k in "${kernels[@]}"; do programs+=("${k%% *}"); done
cmake -S . -B build-portable -G Ninja -DCMAKE_BUILD_TYPE=Release -DNOVELTY_NATIVE=OFF \
  -DNOVELTY_PORTABLE=ON > /dev/null
# Every program (target novelty-programs): scripts/example.sh installs them all.
cmake --build build-portable --parallel "$(nproc)" --target "${programs[@]}" novelty-programs

# The variant the loader picks for a test, e.g. "glibc-hwcaps/x86-64-v3" or "" (baseline).
variant() {
  env ${1:+GLIBC_TUNABLES=$1} LD_DEBUG=libs build-portable/bin/maps_tests \
    --gtest_list_tests 2>&1 | grep -o 'calling init: .*libnovelty_maps[^ ]*' | head -1
}
log=$(mktemp)
for mask in "" "glibc.cpu.hwcaps=-AVX512F" "glibc.cpu.hwcaps=-AVX512F,-AVX2"; do
  echo "portable: ${mask:-no mask}: $(variant "$mask")"
  for k in "${kernels[@]}"; do
    t=${k%% *}
    env ${mask:+GLIBC_TUNABLES=$mask} build-portable/bin/"$t" --gtest_filter="${k#* }" \
      --gtest_brief=1 > "$log" 2>&1 || { cat "$log"; echo "portable: $t failed (${mask:-no mask})"; exit 1; }
  done
done
# Header-only kernels (core/lanes.h, row_windows.h, with_count.h) compile into each test
# program; the portable tests above run their baseline form, these their AVX2 form.
headers="Lanes.*:RowWindows.*:WithCount.*"
# Without precompiled headers or unity batches: that core and its tests include what they use.
cmake -S . -B build-x86-64-v3 -G Ninja -DCMAKE_BUILD_TYPE=Release -DNOVELTY_NATIVE=OFF \
  -DNOVELTY_PCH=OFF -DNOVELTY_UNITY=OFF -DCMAKE_CXX_FLAGS=-march=x86-64-v3 > /dev/null
cmake --build build-x86-64-v3 --parallel "$(nproc)" --target core_tests
build-x86-64-v3/bin/core_tests --gtest_filter="$headers" --gtest_brief=1 > "$log" 2>&1 \
  || { cat "$log"; echo "x86-64-v3: core_tests failed"; exit 1; }
bash scripts/example.sh build-portable
