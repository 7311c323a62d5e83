# `cmake --install build --prefix P`: the CLI, the static library with its public headers, the
# CMake package (find_package(puncture) giving puncture::core), the Python package's modules (the
# CLI's plots run them), the man page; and the CPack settings of `cpack -G DEB`.
include(CMakePackageConfigHelpers)

set(PUNCTURE_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/puncture" CACHE STRING
    "Installation directory of punctureConfig.cmake (relative to the prefix)")

install(TARGETS puncture_core EXPORT punctureTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/puncture
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(TARGETS puncture RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(EXPORT punctureTargets
        NAMESPACE puncture::
        DESTINATION ${PUNCTURE_INSTALL_CMAKEDIR})
configure_package_config_file(
  ${CMAKE_CURRENT_LIST_DIR}/punctureConfig.cmake.in
  ${PROJECT_BINARY_DIR}/punctureConfig.cmake
  INSTALL_DESTINATION ${PUNCTURE_INSTALL_CMAKEDIR})
# 0.x: only the same minor version is compatible.
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/punctureConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/punctureConfig.cmake
              ${PROJECT_BINARY_DIR}/punctureConfigVersion.cmake
        DESTINATION ${PUNCTURE_INSTALL_CMAKEDIR})

# The pure-Python modules of the package, whatever PUNCTURE_BUILD_PYTHON: plot_cli.py draws the
# CLI's --plot and figures (numpy and matplotlib, not the extension).  python/CMakeLists.txt adds
# the extension module beside them when it is built.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/puncture/
        DESTINATION ${PUNCTURE_INSTALL_PYTHONDIR}/puncture
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)

install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The man page puncture(1), generated from `puncture --help` when help2man is installed (Debian:
# help2man); without it the build goes on with no man page.
find_program(HELP2MAN_EXECUTABLE help2man)
if(HELP2MAN_EXECUTABLE AND NOT CMAKE_CROSSCOMPILING)
  set(puncture_man_page ${PROJECT_BINARY_DIR}/man/puncture.1)
  add_custom_command(
    OUTPUT ${puncture_man_page}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/man
    COMMAND ${HELP2MAN_EXECUTABLE} --no-info --no-discard-stderr
            --version-string=${PROJECT_VERSION}
            "--name=membrane puncture by a cylindrical indenter: loading curve, state, puncture point"
            --include=${PROJECT_SOURCE_DIR}/docs/puncture.h2m
            --output=${puncture_man_page} $<TARGET_FILE:puncture>
    DEPENDS puncture ${PROJECT_SOURCE_DIR}/docs/puncture.h2m
    COMMENT "Generating the man page puncture.1 with help2man"
    VERBATIM)
  add_custom_target(puncture_man ALL DEPENDS ${puncture_man_page})
  install(FILES ${puncture_man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man page (Debian: apt-get install help2man)")
endif()

# cpack -G DEB (from the build directory): one package `puncture` with all of the above.
set(CPACK_PACKAGE_NAME puncture)
set(CPACK_PACKAGE_VENDOR "puncture developers")
set(PUNCTURE_DEB_MAINTAINER "puncture maintainers <maintainers@users.noreply.h-seed-4563facc.example>"
    CACHE STRING "Maintainer field of the Debian package")
set(CPACK_PACKAGE_CONTACT "${PUNCTURE_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${PUNCTURE_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "membrane puncture mechanics: C++ library and command-line tool")
set(CPACK_PACKAGE_DESCRIPTION
    "Predicts how a thin rubber membrane, clamped on a circle, deforms and when it punctures as a
rigid cylindrical indenter is pushed into its centre (Liu et al., JMPS 2018): the
force-displacement curve, the deformed shape, the stretch and stress fields and the puncture
point.  The command-line tool puncture, the static library with its headers and CMake package
(find_package(puncture), puncture::core), and the Python modules that draw its plots.")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # puncture_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The libraries the CLI links (dpkg-shlibdeps, from dpkg-dev); the plots run Python with numpy and
# matplotlib, which the program does not link, so they are recommended.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy, python3-matplotlib")
# The static library's users need the headers of its dependencies (punctureConfig.cmake finds
# them).
set(CPACK_DEBIAN_PACKAGE_SUGGESTS
    "cmake, libboost-dev, libfmt-dev, libeigen3-dev, libceres-dev")
include(CPack)
