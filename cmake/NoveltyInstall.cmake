# `cmake --install build --prefix P` installs the libraries, their headers (P/include/novelty/),
# the programs, share/ (P/share/novelty/) and a CMake package: a consumer's CMakeLists.txt says
#
#   find_package(NoveltyMaps 0.1 REQUIRED)
#   target_link_libraries(my_program PRIVATE NoveltyMaps::mrpt)
#
# (examples/CMakeLists.txt does exactly this and CI builds it with default compiler flags).
include(CMakePackageConfigHelpers)

set(NOVELTY_EXPORTED novelty_core novelty_maps novelty_eval novelty_sensors novelty_mrpt)
set(NOVELTY_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/NoveltyMaps)

install(TARGETS ${NOVELTY_EXPORTED} EXPORT NoveltyMapsTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION include/novelty)
install(TARGETS novelty_sim novelty_experiments LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})  # for the programs
install(TARGETS novelty_shell LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})  # for the programs
get_property(novelty_programs GLOBAL PROPERTY novelty_programs)  # every novelty_add_app
install(TARGETS ${novelty_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
add_custom_target(novelty-programs DEPENDS ${novelty_programs})  # what the install needs built
install(DIRECTORY examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/novelty/examples)
foreach(part core maps eval sensors mrpt_plugins)
  install(DIRECTORY ${part} DESTINATION include/novelty FILES_MATCHING PATTERN "*.h")
endforeach()
install(DIRECTORY share/ DESTINATION ${CMAKE_INSTALL_DATADIR}/novelty)

install(EXPORT NoveltyMapsTargets NAMESPACE NoveltyMaps:: DESTINATION ${NOVELTY_CMAKE_DIR})
configure_package_config_file(cmake/NoveltyMapsConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/NoveltyMapsConfig.cmake
                              INSTALL_DESTINATION ${NOVELTY_CMAKE_DIR}
                              PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/NoveltyMapsConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/NoveltyMapsConfig.cmake
              ${PROJECT_BINARY_DIR}/NoveltyMapsConfigVersion.cmake
        DESTINATION ${NOVELTY_CMAKE_DIR})
