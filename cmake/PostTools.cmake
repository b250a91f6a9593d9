# The post-processing tools as commands beside liggghts-crush: one small launcher per entry of
# post/__init__.py's TOOLS (crush-summary, crush-penetration, ...), each bound by its first line to a
# Python that imports numpy, scipy and matplotlib, and the post/ package under share/liggghts-crush.
#
#   LIGGGHTS_CRUSH_PYTHON   the Python the commands are bound to (default: the first of python3 on the
#                           PATH and /usr/bin/python3 that has the three modules)

set(_post_modules numpy scipy matplotlib)
if(NOT LIGGGHTS_CRUSH_PYTHON)
  find_program(_python_on_path NAMES python3 NO_CACHE)
  set(_candidates /usr/bin/python3)
  if(_python_on_path)
    list(PREPEND _candidates "${_python_on_path}")
  endif()
  foreach(_python IN LISTS _candidates)
    if(EXISTS "${_python}")
      execute_process(COMMAND "${_python}" -c "import numpy, scipy, matplotlib; import sys; print(sys.executable)"
                      RESULT_VARIABLE _rc OUTPUT_VARIABLE _exe ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(_rc EQUAL 0)
        # The interpreter itself, not a shim in front of it (pyenv's python3 may change its mind).
        set(LIGGGHTS_CRUSH_PYTHON "${_exe}" CACHE FILEPATH
            "The Python the post-processing commands are bound to (numpy, scipy, matplotlib)")
        break()
      endif()
    endif()
  endforeach()
  if(NOT LIGGGHTS_CRUSH_PYTHON)
    list(GET _candidates 0 _first)
    message(WARNING "liggghts-crush: no Python here imports ${_post_modules}; the post-processing commands "
                    "are bound to ${_first} and will say what is missing (set -DLIGGGHTS_CRUSH_PYTHON=<python>)")
    set(LIGGGHTS_CRUSH_PYTHON "${_first}")
  endif()
endif()
message(STATUS "liggghts-crush: post-processing commands bound to ${LIGGGHTS_CRUSH_PYTHON}")

# The commands, read from post/__init__.py (one place lists them).
set(_tools_source "${PROJECT_SOURCE_DIR}/post/__init__.py")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${_tools_source}")
file(STRINGS "${_tools_source}" _tool_lines REGEX "^    \"crush-[a-z-]+\": \"[a-z_]+\",")
if(NOT _tool_lines)
  message(FATAL_ERROR "post/__init__.py lists no tool in TOOLS")
endif()

# the launchers find share/ relative to themselves (a relocatable install, the Debian package);
# an absolute BINDIR or DATADIR gets the absolute path
if(IS_ABSOLUTE "${CMAKE_INSTALL_BINDIR}" OR IS_ABSOLUTE "${CMAKE_INSTALL_DATADIR}")
  set(_share_from_bin "${CMAKE_INSTALL_FULL_DATADIR}/liggghts-crush")
else()
  file(RELATIVE_PATH _share_from_bin "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix/${_share}")
endif()
set(_launchers "")
foreach(_line IN LISTS _tool_lines)
  string(REGEX MATCH "\"(crush-[a-z-]+)\": \"([a-z_]+)\"" _ "${_line}")
  set(_command "${CMAKE_MATCH_1}")
  set(_module "${CMAKE_MATCH_2}")
  set(_launcher "${CMAKE_BINARY_DIR}/tools/${_command}")
  file(CONFIGURE OUTPUT "${_launcher}" @ONLY CONTENT "#!@LIGGGHTS_CRUSH_PYTHON@
\"\"\"@_command@: liggghts-crush's post/@_module@.py, bound to the Python that has numpy, scipy and matplotlib.\"\"\"
import os
import runpy
import sys

sys.path.insert(0, os.path.normpath(os.path.join(os.path.dirname(os.path.realpath(__file__)), \"@_share_from_bin@\")))
runpy.run_module(\"post.@_module@\", run_name=\"__main__\")
")
  list(APPEND _launchers "${_launcher}")
endforeach()
file(CONFIGURE OUTPUT "${CMAKE_BINARY_DIR}/tools/interpreter" CONTENT "${LIGGGHTS_CRUSH_PYTHON}\n")

install(PROGRAMS ${_launchers} DESTINATION "${CMAKE_INSTALL_BINDIR}" COMPONENT runtime)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/post/" DESTINATION "${_share}/post" COMPONENT runtime
        FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
install(FILES "${CMAKE_BINARY_DIR}/tools/interpreter" DESTINATION "${_share}/post" COMPONENT runtime)
