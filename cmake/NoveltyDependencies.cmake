# Every external dependency of NoveltyMaps, from Debian's packages (scripts/setup.sh installs them).
# A missing one is a configure error that names the package to install.

function(novelty_require found package)
  if(NOT ${found})
    message(FATAL_ERROR "NoveltyMaps: ${package} not found. Run `bash scripts/setup.sh` "
                        "(installs the Debian package ${package}).")
  endif()
endfunction()

find_package(Eigen3 3.3 NO_MODULE QUIET)
novelty_require(Eigen3_FOUND libeigen3-dev)

# Debian builds OpenCV without the non-free xfeatures2d (SURF); contrib is checked by ximgproc.
find_package(OpenCV 4 QUIET COMPONENTS core imgproc imgcodecs features2d video videoio calib3d rgbd
                                       ximgproc bgsegm)
novelty_require(OpenCV_FOUND "libopencv-dev libopencv-contrib-dev")

find_package(MRPT 2.5 QUIET COMPONENTS core system config io serialization img math poses obs maps
                                       opengl vision)
novelty_require(MRPT_FOUND libmrpt-dev)

find_package(Ceres QUIET)
novelty_require(Ceres_FOUND libceres-dev)

find_package(octomap QUIET)
novelty_require(octomap_FOUND liboctomap-dev)
add_library(novelty_octomap INTERFACE)
target_include_directories(novelty_octomap SYSTEM INTERFACE ${OCTOMAP_INCLUDE_DIRS})
target_link_libraries(novelty_octomap INTERFACE ${OCTOMAP_LIBRARIES})

find_package(opengv QUIET)
novelty_require(opengv_FOUND libopengv-dev)

find_package(embree 3 QUIET)
novelty_require(embree_FOUND libembree-dev)

# ODE: the simulator needs double precision (dDOUBLE); Debian's libode-dev is built that way.
find_package(PkgConfig REQUIRED)
pkg_check_modules(ODE QUIET IMPORTED_TARGET ode)
novelty_require(ODE_FOUND libode-dev)
pkg_get_variable(ODE_PRECISION ode precision)
if(NOT ODE_PRECISION STREQUAL "dDOUBLE")
  message(FATAL_ERROR "NoveltyMaps: ODE is built with ${ODE_PRECISION}; double precision needed.")
endif()
add_library(novelty_ode INTERFACE)
target_link_libraries(novelty_ode INTERFACE PkgConfig::ODE)
target_compile_definitions(novelty_ode INTERFACE dIDEDOUBLE)

find_package(Threads REQUIRED)
find_package(ZLIB REQUIRED)
find_package(zstd REQUIRED CONFIG)  # map files' planes (maps/views/plane_codec)  # completeness of MRPT's gzip'd external depth files

find_package(GTest QUIET)
novelty_require(GTest_FOUND "libgtest-dev libgmock-dev")
find_package(benchmark QUIET)
novelty_require(benchmark_FOUND libbenchmark-dev)

message(STATUS "NoveltyMaps dependencies: MRPT ${MRPT_VERSION}, OpenCV ${OpenCV_VERSION}, "
               "Eigen ${Eigen3_VERSION}, Ceres ${Ceres_VERSION}, OctoMap ${OCTOMAP_VERSION}, "
               "OpenGV ${opengv_VERSION}, Embree ${embree_VERSION}, ODE ${ODE_VERSION}")
