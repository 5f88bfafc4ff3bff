// The public headers hold Eigen fixed-size types; their layout must not depend on the instruction
// set a program is compiled for (AVX would make Eigen align them to 32 bytes, AVX-512 to 64). The
// exported targets define EIGEN_MAX_ALIGN_BYTES=16 (cmake/NoveltyOptions.cmake); a program that
// includes a header of ours without it fails here instead of computing garbage or crashing in the
// library. Every header that includes Eigen includes this (ctest eigen_abi_check).
#pragma once

#include <Eigen/Core>

static_assert(EIGEN_MAX_STATIC_ALIGN_BYTES == 16,
              "NoveltyMaps: compile with -DEIGEN_MAX_ALIGN_BYTES=16 (link the NoveltyMaps:: "
              "targets, which set it)");
