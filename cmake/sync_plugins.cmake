# Script mode (cmake -P): copy the plugin folders' files into the LIGGGHTS copy when they differ, and
# rerun LIGGGHTS' Make.sh (style headers and the contact-model template list) when a header or a
# whitelist (style_contact_model_user.whitelist: extra contact-model combinations) changed.
# Arguments: PROJECT_DIR, PLUGIN_DIRS (|-separated), LIGGGHTS_SRC.
string(REPLACE "|" ";" _dirs "${PLUGIN_DIRS}")
set(_headers_changed FALSE)
foreach(_dir IN LISTS _dirs)
  file(GLOB _files "${PROJECT_DIR}/${_dir}/*.cpp" "${PROJECT_DIR}/${_dir}/*.h" "${PROJECT_DIR}/${_dir}/*.whitelist")
  foreach(_f IN LISTS _files)
    get_filename_component(_name "${_f}" NAME)
    set(_dest "${LIGGGHTS_SRC}/${_name}")
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${_f}" "${_dest}" RESULT_VARIABLE _differs
                    OUTPUT_QUIET ERROR_QUIET)
    if(_differs)
      file(COPY_FILE "${_f}" "${_dest}")
      if(_name MATCHES "\\.(h|whitelist)$")
        set(_headers_changed TRUE)
      endif()
    endif()
  endforeach()
endforeach()

if(_headers_changed OR NOT EXISTS "${LIGGGHTS_SRC}/style_contact_model.h")
  message(STATUS "Regenerating LIGGGHTS style headers (Make.sh style, Make.sh models)")
  # Make.sh reuses a stale contact-model whitelist: remove it so new models are listed.
  file(REMOVE "${LIGGGHTS_SRC}/style_contact_model.whitelist")
  foreach(_what style models)
    execute_process(COMMAND sh Make.sh ${_what} WORKING_DIRECTORY "${LIGGGHTS_SRC}"
                    RESULT_VARIABLE _rc OUTPUT_QUIET)
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "LIGGGHTS 'sh Make.sh ${_what}' failed in ${LIGGGHTS_SRC}")
    endif()
  endforeach()
endif()
