# The plain C++ crushing model (no LIGGGHTS, no MPI): the same files are compiled into liggghts.
set(CRUSH_MODEL_SOURCES "")
foreach(_dir IN LISTS LIGGGHTS_CRUSH_PLUGIN_DIRS)
  # Plain model files carry the prefix 'crush_' or 'hertz_mindlin_'; adapters carry LIGGGHTS' prefixes.
  file(GLOB _f CONFIGURE_DEPENDS "${PROJECT_SOURCE_DIR}/${_dir}/crush_*.cpp"
                                 "${PROJECT_SOURCE_DIR}/${_dir}/hertz_mindlin_*.cpp")
  list(APPEND CRUSH_MODEL_SOURCES ${_f})
endforeach()

add_library(crush_model STATIC ${CRUSH_MODEL_SOURCES})
foreach(_dir IN LISTS LIGGGHTS_CRUSH_PLUGIN_DIRS)
  target_include_directories(crush_model PUBLIC "${PROJECT_SOURCE_DIR}/${_dir}")
endforeach()
target_link_libraries(crush_model PUBLIC Eigen3::Eigen)
target_compile_options(crush_model PRIVATE -Wall -Wextra -Wpedantic)
if(LIGGGHTS_CRUSH_COVERAGE)
  target_compile_options(crush_model PUBLIC --coverage -O0)
  target_link_options(crush_model PUBLIC --coverage)
endif()
