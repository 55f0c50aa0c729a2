# `cmake --install BUILD --prefix PREFIX`: the libraries and their headers, the `sled` program,
# the standard library, and the CMake package, so that an outside project writes
#   find_package(sled 0.1 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE sled::sled)
# and includes <sled/sled.h> (tests/install builds examples/embedded exactly so).
#
#   PREFIX/bin/sled                      finds PREFIX/share/sled/stdlib beside itself
#   PREFIX/lib/libsled_*.a               sled::sled (the API), sled::compiler, sled::runtime, ...
#   PREFIX/include/sled/sled.h ...       the public API; the libraries' headers below it
#   PREFIX/share/sled/stdlib/            the standard library (SLED_STDLIB_DIR in the package)
#   PREFIX/lib/cmake/sled/               sledConfig.cmake, its version file and the targets
include(CMakePackageConfigHelpers)

set(SLED_INSTALLED_LIBRARIES sled_lang sled_legacy sled_runtime sled_output sled_compiler sled_api)
set_target_properties(sled_api PROPERTIES EXPORT_NAME sled)
foreach(library IN LISTS SLED_INSTALLED_LIBRARIES)
  if(NOT library STREQUAL "sled_api")
    string(REPLACE "sled_" "" name "${library}")
    set_target_properties(${library} PROPERTIES EXPORT_NAME ${name})
  endif()
endforeach()

install(TARGETS ${SLED_INSTALLED_LIBRARIES} EXPORT sledTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}"
        LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(TARGETS sled RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

# Headers: the API's in include/sled, each library's under include/sled/<folder> as the sources
# include them ("runtime/model/model.h"). The driver's and the report's stay private.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/sled/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/sled"
        FILES_MATCHING PATTERN "*.h")
foreach(folder lang compiler runtime output)
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/${folder}" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/sled"
          FILES_MATCHING PATTERN "*.h" PATTERN "*.def"
          PATTERN "driver" EXCLUDE PATTERN "report" EXCLUDE)
endforeach()

install(DIRECTORY "${PROJECT_SOURCE_DIR}/stdlib/" DESTINATION "${SLED_INSTALL_STDLIB_DIR}")

set(SLED_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/sled")
install(EXPORT sledTargets NAMESPACE sled:: DESTINATION "${SLED_CMAKE_DIR}")
configure_package_config_file("${PROJECT_SOURCE_DIR}/sled/sledConfig.cmake.in"
                              "${PROJECT_BINARY_DIR}/sledConfig.cmake"
                              INSTALL_DESTINATION "${SLED_CMAKE_DIR}"
                              PATH_VARS SLED_INSTALL_STDLIB_DIR)
write_basic_package_version_file("${PROJECT_BINARY_DIR}/sledConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/sledConfig.cmake" "${PROJECT_BINARY_DIR}/sledConfigVersion.cmake"
        DESTINATION "${SLED_CMAKE_DIR}")
