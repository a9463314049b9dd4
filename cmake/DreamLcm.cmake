# LCM 1.3.1 (Debian bookworm) ships neither lcmConfig.cmake nor lcm_wrap_types,
# and its lcm.pc requires glib headers that liblcm-dev does not pull in. So we
# locate the library and header directly and drive lcm-gen ourselves.
find_library(LCM_LIBRARY NAMES lcm REQUIRED)
find_path(LCM_INCLUDE_DIR NAMES lcm/lcm-cpp.hpp REQUIRED)
find_program(LCM_GEN_EXECUTABLE lcm-gen REQUIRED)
find_file(LCM_JAR lcm.jar PATHS /usr/share/java NO_DEFAULT_PATH)

if(NOT TARGET lcm::lcm)
  add_library(lcm::lcm UNKNOWN IMPORTED)
  set_target_properties(lcm::lcm PROPERTIES
    IMPORTED_LOCATION "${LCM_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${LCM_INCLUDE_DIR}")
endif()

# dream_lcm_generate(CPP_DIR <dir> JAVA_DIR <dir> PYTHON_DIR <dir> FILES <.lcm...>
#                    CPP_HEADERS <out-var> JAVA_SOURCES <out-var> PYTHON_SOURCES <out-var>)
# Generates C++ headers, Java sources and pure-Python modules at build time.
function(dream_lcm_generate)
  cmake_parse_arguments(ARG "" "CPP_DIR;JAVA_DIR;PYTHON_DIR;PACKAGE;CPP_HEADERS;JAVA_SOURCES;PYTHON_SOURCES" "FILES" ${ARGN})
  set(cpp_headers)
  set(java_sources)
  set(python_sources)
  foreach(lcm_file IN LISTS ARG_FILES)
    get_filename_component(type_name ${lcm_file} NAME_WE)
    list(APPEND cpp_headers ${ARG_CPP_DIR}/${ARG_PACKAGE}/${type_name}.hpp)
    list(APPEND java_sources ${ARG_JAVA_DIR}/${ARG_PACKAGE}/${type_name}.java)
    list(APPEND python_sources ${ARG_PYTHON_DIR}/${ARG_PACKAGE}/${type_name}.py)
  endforeach()
  add_custom_command(
    OUTPUT ${cpp_headers} ${java_sources} ${python_sources} ${ARG_PYTHON_DIR}/${ARG_PACKAGE}/__init__.py
    COMMAND ${CMAKE_COMMAND} -E make_directory ${ARG_CPP_DIR} ${ARG_JAVA_DIR} ${ARG_PYTHON_DIR}
    COMMAND ${LCM_GEN_EXECUTABLE} --cpp --cpp-std c++11 --cpp-hpath ${ARG_CPP_DIR} ${ARG_FILES}
    COMMAND ${LCM_GEN_EXECUTABLE} --java --jpath ${ARG_JAVA_DIR} ${ARG_FILES}
    COMMAND ${LCM_GEN_EXECUTABLE} --python --ppath ${ARG_PYTHON_DIR} ${ARG_FILES}
    DEPENDS ${ARG_FILES}
    COMMENT "lcm-gen: C++, Java and Python types for package ${ARG_PACKAGE}"
    VERBATIM)
  set(${ARG_CPP_HEADERS} ${cpp_headers} PARENT_SCOPE)
  set(${ARG_JAVA_SOURCES} ${java_sources} PARENT_SCOPE)
  set(${ARG_PYTHON_SOURCES} ${python_sources} PARENT_SCOPE)
endfunction()
