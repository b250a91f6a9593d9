# Runs liggghts on DECK in WORKDIR and checks that it ran to the end and kept its particles.
file(REMOVE_RECURSE "${WORKDIR}")
file(MAKE_DIRECTORY "${WORKDIR}")
# LIGGGHTS exits with status 1 after printing its help: judge by the output.
execute_process(COMMAND "${LIGGGHTS}" -h OUTPUT_VARIABLE _help ERROR_VARIABLE _help)
if(NOT _help MATCHES "Style options compiled with this executable")
  message(FATAL_ERROR "liggghts -h did not print its style list:\n${_help}")
endif()
# The plugin's styles must be compiled in (the list grows with later issues).
string(REPLACE "|" ";" _styles "${EXPECTED_STYLES}")
foreach(_style IN LISTS _styles)
  if(NOT _help MATCHES "${_style}")
    message(FATAL_ERROR "liggghts -h does not list the style '${_style}'")
  endif()
endforeach()
# LAUNCHER: an optional |-separated MPI launcher prefix (mpiexec -n 2 ...).
string(REPLACE "|" ";" _launcher "${LAUNCHER}")
execute_process(COMMAND ${_launcher} "${LIGGGHTS}" -in "${DECK}" -log log.smoke WORKING_DIRECTORY "${WORKDIR}"
                OUTPUT_VARIABLE _out ERROR_VARIABLE _err RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "liggghts -in ${DECK} failed (exit ${_rc}):\n${_out}\n${_err}")
endif()
if(NOT _out MATCHES "SMOKE_DONE atoms=100")
  message(FATAL_ERROR "the smoke deck did not end with its 100 particles:\n${_out}")
endif()
message(STATUS "smoke deck ran to the end with 100 particles")
