# Build options shared by every NoveltyMaps target.
#
#   NOVELTY_WERROR     (ON)  treat compiler warnings in our code as errors
#   NOVELTY_SANITIZE   (OFF) build with AddressSanitizer + UndefinedBehaviorSanitizer
#   NOVELTY_FUZZ       (OFF) with clang: the libFuzzer targets of tests/fuzz, every library
#                            instrumented for them (scripts/sanitize.sh builds both)
#   NOVELTY_NATIVE     (ON)  -march=native: the per-pixel kernels are vectorised with Eigen and
#                            need AVX2/FMA to meet the budgets of DESIGN.md; binaries are built on
#                            the machine that runs them, so this is safe. Turn off to ship binaries
#                            (NOVELTY_PORTABLE does, and still uses AVX2/AVX-512 where the CPU has it).
#   NOVELTY_PORTABLE   (OFF) binaries for any x86-64: the libraries with SIMD kernels are built
#                            for the baseline and again for x86-64-v3 and x86-64-v4, and glibc's
#                            loader picks the variant the CPU runs (glibc-hwcaps). For packages.
#   NOVELTY_PCH        (ON)  precompiled headers (the standard library, Eigen, OpenCV, MRPT, and
#                            GoogleTest for tests): 42 % less compile time (plain build).
#                            Turn off to check that every file includes what it uses.
#   NOVELTY_UNITY      (ON)  unity builds: each library's sources, and each part's tests, are
#                            compiled NOVELTY_UNITY_BATCH (8) files at a time, so the headers they
#                            share are parsed and their templates instantiated once per batch:
#                            a fresh build takes 5.5 min instead of 15 on 2 cores. Turn off for
#                            the quickest rebuild of one changed file, and to check that every
#                            file includes what it uses.
#   BUILD_SHARED_LIBS  (ON)  shared libraries: a program that uses the installed package links
#                            NoveltyMaps::mrpt and nothing else, and the maps register on load.
#
# The public headers hold Eigen fixed-size types (poses, cameras). Their alignment is fixed at
# 16 bytes for every build and every consumer (EIGEN_MAX_ALIGN_BYTES, exported with the targets):
# otherwise a library built with AVX-512 (64) and a program built with default flags (16) lay the
# same struct out differently and crash. 16 is what Debian's Eigen users (OpenGV, Ceres) use.

option(NOVELTY_WERROR "Treat warnings as errors in NoveltyMaps code" ON)
option(NOVELTY_SANITIZE "Build with address and undefined-behaviour sanitizers" OFF)
option(NOVELTY_NATIVE "Optimise for the build machine's CPU (-march=native)" ON)
option(BUILD_SHARED_LIBS "Build NoveltyMaps' libraries as shared libraries" ON)
option(NOVELTY_FUZZ "Build the libFuzzer targets of tests/fuzz (clang; all our code instrumented)" OFF)
option(NOVELTY_PORTABLE "Build for any x86-64, with AVX2/AVX-512 variants chosen at run time" OFF)
option(NOVELTY_PCH "Precompile the third-party headers every file includes" ON)
option(NOVELTY_UNITY "Compile the sources of each library and test program in batches" ON)
set(NOVELTY_UNITY_BATCH 8 CACHE STRING "Source files per unity batch (NOVELTY_UNITY)")
set(CMAKE_UNITY_BUILD ${NOVELTY_UNITY})
set(CMAKE_UNITY_BUILD_BATCH_SIZE ${NOVELTY_UNITY_BATCH})
if(NOVELTY_PORTABLE)
  if(NOVELTY_NATIVE)
    message(FATAL_ERROR "NOVELTY_PORTABLE=ON needs NOVELTY_NATIVE=OFF (-march=native is not portable)")
  endif()
  if(NOT BUILD_SHARED_LIBS)
    message(FATAL_ERROR "NOVELTY_PORTABLE=ON needs BUILD_SHARED_LIBS=ON (variants are shared libraries)")
  endif()
endif()
set(NOVELTY_SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
set(NOVELTY_EIGEN_ALIGNMENT EIGEN_MAX_ALIGN_BYTES=16)

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
# In a unity batch every source is an included file, so GCC warns about each class that holds a
# type of its own file's anonymous namespace (a pimpl's members): true of any included file, and
# harmless here, where the class is defined and used in that one source.
if(NOVELTY_UNITY AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(novelty_build_flags INTERFACE -Wno-subobject-linkage)
endif()
if(NOVELTY_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "NOVELTY_FUZZ=ON needs clang (libFuzzer): CXX=clang++ cmake ...")
  endif()
  target_compile_options(novelty_build_flags INTERFACE -fsanitize=fuzzer-no-link)
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

# Precompiled headers: the third-party headers nearly every file includes. Parsing them is a large
# part of a compile (a test using MRPT spends 6 of its 16 s on them); with these, each library,
# each variant and each kind of test (tests/CMakeLists.txt) parses them once.
set(NOVELTY_PCH_HEADERS <algorithm> <cmath> <cstdint> <limits> <memory> <optional> <stdexcept>
    <string> <vector> <Eigen/Core> <Eigen/Geometry> <opencv2/core.hpp> <opencv2/imgproc.hpp>)
# ...and, for targets that depend on MRPT (sensors and above), its observations and archives.
set(NOVELTY_PCH_MRPT_HEADERS <mrpt/obs/CObservation3DRangeScan.h> <mrpt/serialization/CArchive.h>)

# novelty_precompile_headers(TARGET DEPS... [EXTRA <header>...]): TARGET precompiles the headers
# that its dependencies DEPS provide, and EXTRA.
function(novelty_precompile_headers target)
  if(NOT NOVELTY_PCH)
    return()
  endif()
  cmake_parse_arguments(ARG "" "" "EXTRA" ${ARGN})
  set(headers ${NOVELTY_PCH_HEADERS})
  set(with_mrpt ${ARG_UNPARSED_ARGUMENTS})
  list(FILTER with_mrpt INCLUDE REGEX "^(mrpt::.*|novelty_sensors|novelty_mrpt|novelty_sim)$")
  if(with_mrpt)
    list(APPEND headers ${NOVELTY_PCH_MRPT_HEADERS})
  endif()
  target_precompile_headers(${target} PRIVATE ${headers} ${ARG_EXTRA})
endfunction()

# novelty_add_library(NAME [KERNELS] SOURCES... [DEPS ...])
# A library of our own: our warnings and flags, includes rooted at the project top so headers are
# included as "maps/stats/normal_gamma.h".
# KERNELS: the library holds SIMD kernels; with NOVELTY_PORTABLE it is also built for x86-64-v3
# (AVX2, FMA, F16C) and x86-64-v4 (AVX-512), chosen at run time (novelty_add_hwcaps_variant).
# Installed (cmake --install) and exported as NoveltyMaps::<NAME without "novelty_">, with its
# headers under include/novelty/ (see cmake/NoveltyInstall.cmake).
function(novelty_add_library name)
  cmake_parse_arguments(ARG "KERNELS" "" "SOURCES;DEPS" ${ARGN})
  add_library(${name} ${ARG_SOURCES})
  string(REPLACE "novelty_" "" export_name ${name})
  add_library(NoveltyMaps::${export_name} ALIAS ${name})
  target_include_directories(${name} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                            $<INSTALL_INTERFACE:include/novelty>)
  target_compile_definitions(${name} PUBLIC ${NOVELTY_EIGEN_ALIGNMENT})
  # BUILD_INTERFACE: our warning flags are not part of the exported interface (a static build
  # would otherwise export them).
  target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE $<BUILD_INTERFACE:novelty_build_flags>)
  target_compile_features(${name} PUBLIC cxx_std_17)
  # Inline functions stay inside each library: those taking SIMD vector types by value are
  # compiled differently per variant (x86-64, -v3, -v4), and one copy must not replace another.
  target_compile_options(${name} PRIVATE -fvisibility-inlines-hidden)
  novelty_precompile_headers(${name} ${ARG_DEPS})
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON
                                           INSTALL_RPATH "$ORIGIN"
                                           EXPORT_NAME ${export_name}
                                           VERSION ${PROJECT_VERSION}
                                           SOVERSION ${NOVELTY_SOVERSION})
  if(NOVELTY_PORTABLE AND ARG_KERNELS)
    foreach(level x86-64-v3 x86-64-v4)
      novelty_add_hwcaps_variant(${name} ${level} "${ARG_SOURCES}")
    endforeach()
  endif()
endfunction()

# The same library built for a micro-architecture level and placed in glibc-hwcaps/<level>/ beside
# it: the dynamic loader (glibc >= 2.33) loads the best variant the CPU runs, so one build is fast
# on AVX2 and AVX-512 machines and still runs on any x86-64. The ABI is the same (same sources,
# same Eigen alignment, same SONAME).
function(novelty_add_hwcaps_variant name level sources)
  string(REPLACE "-" "_" suffix ${level})
  set(variant ${name}_${suffix})
  add_library(${variant} SHARED ${sources})
  get_target_property(deps ${name} LINK_LIBRARIES)
  target_link_libraries(${variant} PRIVATE ${deps})
  target_include_directories(${variant} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_definitions(${variant} PRIVATE ${NOVELTY_EIGEN_ALIGNMENT})
  target_compile_options(${variant} PRIVATE -march=${level} -fvisibility-inlines-hidden)
  novelty_precompile_headers(${variant} ${deps})  # its own: built for its level
  set_target_properties(${variant} PROPERTIES
    OUTPUT_NAME ${name} VERSION ${PROJECT_VERSION} SOVERSION ${NOVELTY_SOVERSION}
    LIBRARY_OUTPUT_DIRECTORY ${CMAKE_LIBRARY_OUTPUT_DIRECTORY}/glibc-hwcaps/${level}
    INSTALL_RPATH "$ORIGIN/../..")  # its dependencies (and their variants) are two folders up
  add_dependencies(${name} ${variant})  # whatever runs the library finds its variants built
  install(TARGETS ${variant} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/glibc-hwcaps/${level})
endfunction()

# novelty_add_app(NAME SOURCE [DEPS ...]) -> build/bin/NAME
# Every program is a shell over novelty_shell (apps/shell/program.h) and is installed.
function(novelty_add_app name source)
  cmake_parse_arguments(ARG "" "" "DEPS" ${ARGN})
  add_executable(${name} ${source})
  target_link_libraries(${name} PRIVATE novelty_shell ${ARG_DEPS} novelty_build_flags)
  set_property(GLOBAL APPEND PROPERTY novelty_programs ${name})
endfunction()
