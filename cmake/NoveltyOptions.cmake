# Build options shared by every NoveltyMaps target.
#
#   NOVELTY_WERROR     (ON)  treat compiler warnings in our code as errors
#   NOVELTY_SANITIZE   (OFF) build with AddressSanitizer + UndefinedBehaviorSanitizer
#   NOVELTY_NATIVE     (ON)  -march=native: the per-pixel kernels are vectorised with Eigen and
#                            need AVX2/FMA to meet the budgets of DESIGN.md; binaries are built on
#                            the machine that runs them, so this is safe. Turn off to ship binaries.

option(NOVELTY_WERROR "Treat warnings as errors in NoveltyMaps code" ON)
option(NOVELTY_SANITIZE "Build with address and undefined-behaviour sanitizers" OFF)
option(NOVELTY_NATIVE "Optimise for the build machine's CPU (-march=native)" ON)

add_library(novelty_build_flags INTERFACE)
target_compile_options(novelty_build_flags INTERFACE -Wall -Wextra -Wpedantic -Wshadow
                                                     -Wnon-virtual-dtor -Wno-psabi)
if(NOVELTY_WERROR)
  target_compile_options(novelty_build_flags INTERFACE -Werror)
endif()
if(NOVELTY_NATIVE)
  target_compile_options(novelty_build_flags INTERFACE -march=native)
endif()
# GCC 12 reports its own AVX/AVX-512 intrinsic headers as using uninitialised values when Eigen
# vectorises with them (GCC bug 105593), and with -march=x86-64-v3 an Eigen::Vector3d read as a
# 256-bit AVX load as partly out of bounds (photometric_alignment.cc); these warnings are not
# about our code. Not only with NOVELTY_NATIVE: binaries shipped with e.g.
# CMAKE_CXX_FLAGS=-march=x86-64-v3 hit them too.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(novelty_build_flags INTERFACE -Wno-uninitialized
                                                       -Wno-maybe-uninitialized -Wno-array-bounds)
endif()
if(NOVELTY_SANITIZE)
  # Alignment checks are off: MRPT 2.5 declares its OpenGL classes 32-byte aligned
  # (MRPT_MAX_ALIGN_BYTES) but its own factories (e.g. CFrustum::Create) allocate them at 16, so
  # UBSan flags MRPT, not us. Every other UBSan check stays fatal.
  target_compile_options(novelty_build_flags INTERFACE -fsanitize=address,undefined
                                                       -fno-sanitize=alignment
                                                       -fno-omit-frame-pointer
                                                       -fno-sanitize-recover=undefined)
  target_link_options(novelty_build_flags INTERFACE -fsanitize=address,undefined
                                                    -fno-sanitize=alignment)
endif()

# novelty_add_library(NAME SOURCES... [DEPS ...])
# A library of our own: our warnings and flags, includes rooted at the project top so headers are
# included as "maps/stats/normal_gamma.h".
function(novelty_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE novelty_build_flags)
  # Dependencies' headers are system headers: their warnings are not ours to fix.
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
endfunction()

# novelty_add_app(NAME SOURCE [DEPS ...]) -> build/bin/NAME
function(novelty_add_app name source)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} novelty_build_flags)
endfunction()
