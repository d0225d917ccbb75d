# Packaging: `cmake --install` puts the headers, tailor::tailor, tailor::sim, the `tailor`
# CLI and a tailorConfig.cmake into the prefix, so that a consumer needs only
#   find_package(tailor CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE tailor::tailor)   # or tailor::sim
#   #include "tailor/tailor.hpp"                          // the front door
# The consumer in examples/ is built against an installed copy by the test below.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TAILOR_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/tailor" CACHE STRING
    "Where tailorConfig.cmake is installed, relative to the prefix")

set_target_properties(tailor PROPERTIES EXPORT_NAME tailor)
set_target_properties(tailor_sim PROPERTIES EXPORT_NAME sim)
install(TARGETS tailor tailor_sim EXPORT tailorTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS tailor_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The headers of every module of both libraries (a module added to the lists is installed).
foreach(module ${TAILOR_CORE_MODULES} ${TAILOR_SIM_MODULES})
  install(DIRECTORY src/tailor/${module} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tailor
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
# The front door, tailor/tailor.hpp (the core library's public API in one include).
install(FILES src/tailor/tailor.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tailor)

install(EXPORT tailorTargets NAMESPACE tailor:: FILE tailorTargets.cmake
        DESTINATION ${TAILOR_INSTALL_CMAKEDIR})
configure_package_config_file(cmake/tailorConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/tailorConfig.cmake
                              INSTALL_DESTINATION ${TAILOR_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/tailorConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/tailorConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/tailorConfigVersion.cmake
              ${CMAKE_CURRENT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake
        DESTINATION ${TAILOR_INSTALL_CMAKEDIR})

# The consumer test: install this build into a scratch prefix, then configure, build and
# run examples/ against it alone (so a broken export or a missing header fails `make test`).
if(TAILOR_BUILD_TESTS)
  set(TAILOR_EXAMPLE_WORK_DIR ${CMAKE_CURRENT_BINARY_DIR}/example-consumer)
  # From scratch every time: no header left over from an older install, no cached config.
  add_test(NAME package.clean
           COMMAND ${CMAKE_COMMAND} -E rm -rf ${TAILOR_EXAMPLE_WORK_DIR})
  add_test(NAME package.install
           COMMAND ${CMAKE_COMMAND} -E env --unset=DESTDIR
                   ${CMAKE_COMMAND} --install ${CMAKE_CURRENT_BINARY_DIR}
                   --prefix ${TAILOR_EXAMPLE_WORK_DIR}/prefix --config $<CONFIG>)
  add_test(NAME package.consumer
           COMMAND ${CMAKE_CTEST_COMMAND}
                   --build-and-test ${CMAKE_CURRENT_SOURCE_DIR}/examples
                                    ${TAILOR_EXAMPLE_WORK_DIR}/build
                   --build-generator ${CMAKE_GENERATOR}
                   --build-options -DCMAKE_PREFIX_PATH=${TAILOR_EXAMPLE_WORK_DIR}/prefix
                                   -DCMAKE_BUILD_TYPE=$<CONFIG>
                                   -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}
                                   "-DCMAKE_CXX_FLAGS=${CMAKE_CXX_FLAGS}"
                                   "-DCMAKE_EXE_LINKER_FLAGS=${CMAKE_EXE_LINKER_FLAGS}"
                   --test-command detect_step
                                  ${TAILOR_DATA_DIR}/thick-cloth/t0.ply
                                  ${TAILOR_DATA_DIR}/thick-cloth/t1.ply)
  set_tests_properties(package.clean PROPERTIES FIXTURES_SETUP tailor_package_clean)
  set_tests_properties(package.install PROPERTIES FIXTURES_REQUIRED tailor_package_clean
                                                  FIXTURES_SETUP tailor_installed)
  set_tests_properties(package.consumer PROPERTIES
                       FIXTURES_REQUIRED tailor_installed
                       PASS_REGULAR_EXPRESSION "collisions: [0-9]+ vertex-face, [0-9]+ edge-edge")
endif()
