#!/usr/bin/env bash
# The SIMD kernels built for aarch64 (NEON) with Debian's cross compiler and their tests run
# under qemu-user: core/lanes.h against each function's lane-by-lane definition, and the
# normal-gamma packet kernel against its double-precision reference. These files need neither
# OpenCV nor MRPT, so no arm64 libraries are installed: the tests link GoogleTest built from
# Debian's sources (/usr/src/googletest) and are linked statically. Output in build-aarch64/.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build-aarch64
cxx=aarch64-linux-gnu-g++
gtest=/usr/src/googletest/googletest
mkdir -p "$out"
# GCC 12's false uninitialised-value reports in its own intrinsic headers (cmake/NoveltyOptions.cmake).
flags=(-std=c++17 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wno-psabi -Werror
       -Wno-uninitialized -Wno-maybe-uninitialized -DEIGEN_MAX_ALIGN_BYTES=16 -I.
       -isystem /usr/include/eigen3 -isystem "$gtest/include")
if [ ! -f "$out/libgtest.a" ]; then
  "$cxx" -std=c++17 -O1 -isystem "$gtest/include" -I"$gtest" -c "$gtest/src/gtest-all.cc" \
    -o "$out/gtest-all.o"
  "$cxx" -std=c++17 -O1 -isystem "$gtest/include" -c "$gtest/src/gtest_main.cc" \
    -o "$out/gtest_main.o"
  aarch64-linux-gnu-ar rcs "$out/libgtest.a" "$out/gtest-all.o" "$out/gtest_main.o"
fi
sources=(core/lanes_test.cc core/with_count_test.cc maps/stats/normal_gamma_packets_test.cc)
kernels=(maps/stats/normal_gamma_packets.cc maps/stats/normal_gamma.cc maps/stats/normal_gamma_kl.cc)
"$cxx" "${flags[@]}" "${sources[@]/#/tests/}" "${kernels[@]}" "$out/libgtest.a" -static -pthread \
  -o "$out/kernel_tests"
echo "aarch64: $(aarch64-linux-gnu-readelf -h "$out/kernel_tests" | grep -o "Machine:.*")"
qemu-aarch64 "$out/kernel_tests" --gtest_brief=1
