# Install and package the liggghts executable with the plugin compiled in.
#
#   cmake --install build                  # to the prefix (default ~/.local): bin/liggghts-crush,
#                                          # bin/liggghts and the post-processing commands bin/crush-*,
#                                          # doc pages, examples and post/ under share/
#   cd build && cpack -G DEB               # liggghts-crush_<version>_<arch>.deb: /usr/bin/liggghts-crush
#
# The binary is liggghts-crush everywhere, so it can sit beside Debian's own 'liggghts' package
# (/usr/bin/liggghts, without the plugin). A user install also gets a 'liggghts' link to it (component
# alias), so decks run as LIGGGHTS users type them; the Debian package leaves the link out.

if(CMAKE_INSTALL_PREFIX_INITIALIZED_TO_DEFAULT AND DEFINED ENV{HOME})
  set(CMAKE_INSTALL_PREFIX "$ENV{HOME}/.local" CACHE PATH "Install prefix" FORCE)
endif()
include(GNUInstallDirs)

set(_share "${CMAKE_INSTALL_DATADIR}/liggghts-crush")
set(_doc "${CMAKE_INSTALL_DATADIR}/doc/liggghts-crush")

install(PROGRAMS "$<TARGET_FILE:liggghts>" DESTINATION "${CMAKE_INSTALL_BINDIR}" RENAME liggghts-crush
        COMPONENT runtime)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/examples/" DESTINATION "${_share}/examples" COMPONENT runtime
        FILES_MATCHING PATTERN "in.*" PATTERN "*.py" PATTERN "*.stl")
# post/ as a package under share/, and its commands (crush-summary, ...) beside the binary.
include(${CMAKE_CURRENT_LIST_DIR}/PostTools.cmake)
install(FILES "${PROJECT_SOURCE_DIR}/README.md" DESTINATION "${_doc}" COMPONENT runtime)
# doc/ and studies/ side by side, as in the repository, so that the pages' relative links hold
install(DIRECTORY "${PROJECT_SOURCE_DIR}/doc/" DESTINATION "${_doc}/doc" COMPONENT runtime)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/studies/" DESTINATION "${_doc}/studies" COMPONENT runtime)
install(CODE "file(CREATE_LINK liggghts-crush \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/liggghts\" SYMBOLIC)
              message(STATUS \"Installing: \$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}/liggghts -> liggghts-crush\")"
        COMPONENT alias)

# Debian package of the runtime component alone (no 'liggghts' link): it installs beside Debian's
# liggghts, never over it. Dependencies come from dpkg-shlibdeps (package dpkg-dev).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME liggghts-crush)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "liggghts-crush maintainers <liggghts-crush@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "LIGGGHTS 3.8.0 with grain crushing (Ciantia et al. 2014) compiled in, as liggghts-crush")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};${PROJECT_NAME};runtime;/")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "openmpi-bin, python3-matplotlib, python3-numpy")
include(CPack)
