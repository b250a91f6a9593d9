# Obtain the LIGGGHTS 3.8.0 source and prepare a patched, writable copy in the build directory.
#
#   LIGGGHTS_SOURCE_DIR  an existing LIGGGHTS tree (top level, holding src/); never modified
#   LIGGGHTS_TARBALL     a LIGGGHTS source tarball (default: Debian's liggghts_3.8.0+repack1.orig.tar.xz,
#                        fetched by scripts/setup.sh into .downloads/)
#   LIGGGHTS_TARBALL_SHA256  expected checksum of the tarball (empty: do not check)
#
# Result: LIGGGHTS_SRC = <build>/liggghts-3.8.0/src, patched with patches/*.patch in order.

set(LIGGGHTS_DEBIAN_TARBALL_NAME "liggghts_3.8.0+repack1.orig.tar.xz")
set(LIGGGHTS_SOURCE_DIR "" CACHE PATH "Existing LIGGGHTS source tree to build from (copied, never modified)")
set(LIGGGHTS_TARBALL "${PROJECT_SOURCE_DIR}/.downloads/${LIGGGHTS_DEBIAN_TARBALL_NAME}"
    CACHE FILEPATH "LIGGGHTS 3.8.0 source tarball")
set(LIGGGHTS_TARBALL_SHA256 "c18721d9a870c5170f03b91e4f1ffe13335c66ed1f0ff2c64ebd3be91c37867a"
    CACHE STRING "SHA256 of LIGGGHTS_TARBALL (empty: skip the check)")

set(LIGGGHTS_COPY "${CMAKE_BINARY_DIR}/liggghts-3.8.0")
set(LIGGGHTS_SRC "${LIGGGHTS_COPY}/src")
# A patch added or edited re-runs the configuration, which redoes the copy (the stamp below).
file(GLOB LIGGGHTS_PATCHES CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/patches/*.patch")
list(SORT LIGGGHTS_PATCHES)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${LIGGGHTS_PATCHES})

# A stamp that changes whenever the origin or a patch changes: the copy is redone then, not otherwise.
if(LIGGGHTS_SOURCE_DIR)
  if(NOT EXISTS "${LIGGGHTS_SOURCE_DIR}/src/lammps.cpp")
    message(FATAL_ERROR "LIGGGHTS_SOURCE_DIR=${LIGGGHTS_SOURCE_DIR} is not a LIGGGHTS tree "
                        "(expected ${LIGGGHTS_SOURCE_DIR}/src/lammps.cpp)")
  endif()
  set(_origin "dir:${LIGGGHTS_SOURCE_DIR}")
else()
  if(NOT EXISTS "${LIGGGHTS_TARBALL}")
    message(FATAL_ERROR "LIGGGHTS source tarball not found: ${LIGGGHTS_TARBALL} - expected Debian's "
                        "${LIGGGHTS_DEBIAN_TARBALL_NAME}; run 'bash scripts/setup.sh' to fetch it, or pass "
                        "-DLIGGGHTS_TARBALL=<tarball> or -DLIGGGHTS_SOURCE_DIR=<tree>")
  endif()
  file(SHA256 "${LIGGGHTS_TARBALL}" _sha)
  if(LIGGGHTS_TARBALL_SHA256 AND NOT _sha STREQUAL LIGGGHTS_TARBALL_SHA256)
    message(FATAL_ERROR "LIGGGHTS tarball ${LIGGGHTS_TARBALL} has SHA256 ${_sha}, expected "
                        "${LIGGGHTS_TARBALL_SHA256} (Debian liggghts 3.8.0+repack1); re-fetch it with "
                        "'bash scripts/setup.sh', or pass -DLIGGGHTS_TARBALL_SHA256= for another release")
  endif()
  set(_origin "tar:${_sha}")
endif()
set(_stamp_text "${_origin}")
foreach(_p IN LISTS LIGGGHTS_PATCHES)
  file(SHA256 "${_p}" _psha)
  string(APPEND _stamp_text "\n${_p}:${_psha}")
endforeach()

set(_stamp "${LIGGGHTS_COPY}/.liggghts-crush-prepared")
set(_old_stamp "")
if(EXISTS "${_stamp}")
  file(READ "${_stamp}" _old_stamp)
endif()

if(NOT _old_stamp STREQUAL _stamp_text)
  message(STATUS "liggghts-crush: preparing patched LIGGGHTS source in ${LIGGGHTS_COPY}")
  file(REMOVE_RECURSE "${LIGGGHTS_COPY}")
  if(LIGGGHTS_SOURCE_DIR)
    file(COPY "${LIGGGHTS_SOURCE_DIR}/src" DESTINATION "${LIGGGHTS_COPY}"
         PATTERN "Obj_*" EXCLUDE PATTERN "*.o" EXCLUDE PATTERN "*.d" EXCLUDE)
  else()
    set(_unpack "${CMAKE_BINARY_DIR}/liggghts-unpack")
    file(REMOVE_RECURSE "${_unpack}")
    file(MAKE_DIRECTORY "${_unpack}")
    execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf "${LIGGGHTS_TARBALL}"
                    WORKING_DIRECTORY "${_unpack}" RESULT_VARIABLE _rc)
    file(GLOB _top LIST_DIRECTORIES true "${_unpack}/*/src")
    if(NOT _rc EQUAL 0 OR NOT _top)
      message(FATAL_ERROR "could not unpack ${LIGGGHTS_TARBALL} into a tree with src/ (tar exit ${_rc})")
    endif()
    get_filename_component(_top "${_top}" DIRECTORY)
    file(RENAME "${_top}" "${LIGGGHTS_COPY}")
    file(REMOVE_RECURSE "${_unpack}")
  endif()
  # Generated files of an earlier build in a user's tree must not leak into ours.
  file(GLOB _generated "${LIGGGHTS_SRC}/style_*.h" "${LIGGGHTS_SRC}/style_contact_model*.whitelist")
  if(_generated)
    file(REMOVE ${_generated})
  endif()
  find_program(PATCH_PROGRAM patch REQUIRED)
  foreach(_p IN LISTS LIGGGHTS_PATCHES)
    execute_process(COMMAND ${PATCH_PROGRAM} -p1 --forward --batch -i "${_p}"
                    WORKING_DIRECTORY "${LIGGGHTS_COPY}" RESULT_VARIABLE _rc OUTPUT_VARIABLE _out
                    ERROR_VARIABLE _out)
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "patch ${_p} does not apply to the LIGGGHTS source:\n${_out}")
    endif()
    get_filename_component(_pn "${_p}" NAME)
    message(STATUS "liggghts-crush: applied ${_pn}")
  endforeach()
  file(WRITE "${_stamp}" "${_stamp_text}")
endif()
