# `cmake --install build --prefix P` puts in place what a controller written
# out of tree needs (docs/writing-a-controller.md):
#   P/bin          dream, dream-agent, dream-agent-shared
#   P/lib          the dream shared libraries
#   P/include      public headers of the exported libraries, and the C++ lcmtypes
#   P/lib/cmake/dream  the CMake package: find_package(dream) -> dream::agent_host ...
#   P/share/dream/java    dream_lcmtypes.jar (dream spy)
#   P/share/dream/python  the Python lcmtypes (package dream) and python/*.py
#   P/share/dream/python-runtime  the Python controller runtime (python/dream) and the rps of scripts (python/rps_dream)
#   P/share/dream/bridge  the check-submission runner and stand-in simulator
include(CMakePackageConfigHelpers)

set(DREAM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/dream)
set(DREAM_INSTALL_DATADIR ${CMAKE_INSTALL_DATADIR}/dream)

# Every library target below `dir` (the tools need all of them at run time,
# including those added later by other folders).
function(dream_library_targets dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  set(libraries)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "SHARED_LIBRARY")
      list(APPEND libraries ${target})
    endif()
  endforeach()
  foreach(subdir IN LISTS subdirs)
    dream_library_targets(${subdir} sub_libraries)
    list(APPEND libraries ${sub_libraries})
  endforeach()
  set(${out} ${libraries} PARENT_SCOPE)
endfunction()

# What a controller builds against, as dream::<name>.
# The built-in kinds (agents/kinds/) too: the agent host links them.
set(DREAM_EXPORTED_LIBRARIES robotarium barriers world config files run_config msgs lcm run_log agents kind_api ${DREAM_BUILT_IN_KINDS}
  agent_host)
set(exported_targets)
foreach(name IN LISTS DREAM_EXPORTED_LIBRARIES)
  set_target_properties(dream_${name} PROPERTIES EXPORT_NAME ${name})
  list(APPEND exported_targets dream_${name})
endforeach()
install(TARGETS ${exported_targets}
  EXPORT dreamTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

dream_library_targets(${PROJECT_SOURCE_DIR} all_libraries)
set(runtime_only_libraries ${all_libraries})
list(REMOVE_ITEM runtime_only_libraries ${exported_targets})
if(all_libraries)
  dream_library_version(${all_libraries})
endif()
if(runtime_only_libraries)
  install(TARGETS ${runtime_only_libraries} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} NAMELINK_SKIP)
endif()

install(TARGETS dream dream-agent dream-agent-shared RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(DIRECTORY
    ${PROJECT_SOURCE_DIR}/base/robotarium/include/
    ${PROJECT_SOURCE_DIR}/base/config/include/
    ${PROJECT_SOURCE_DIR}/base/run_log/include/
    ${PROJECT_SOURCE_DIR}/lcmtypes/lcm/include/
    ${PROJECT_SOURCE_DIR}/sim/world/include/
    ${PROJECT_SOURCE_DIR}/sim/run_config/include/
    ${PROJECT_SOURCE_DIR}/agents/include/
    ${PROJECT_SOURCE_DIR}/agents/barriers/include/
    ${PROJECT_SOURCE_DIR}/agents/kind_api/include/
    ${PROJECT_SOURCE_DIR}/agents/agent_host/include/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h")
foreach(kind IN LISTS DREAM_BUILT_IN_KINDS)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/agents/kinds/${kind}/include/
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
endforeach()
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcmtypes/generated/cpp/
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")

install(FILES ${DREAM_TYPES_JAR} DESTINATION ${DREAM_INSTALL_DATADIR}/java)
install(DIRECTORY ${PROJECT_BINARY_DIR}/python/dream
  DESTINATION ${DREAM_INSTALL_DATADIR}/python
  FILES_MATCHING PATTERN "*.py")
install(FILES ${PROJECT_SOURCE_DIR}/python/dream_log.py DESTINATION ${DREAM_INSTALL_DATADIR}/python)
# The Python controller runtime (package dream) apart from lcm-gen's package of
# the same name: the tools that host Python controllers join the two.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/dream
  DESTINATION ${DREAM_INSTALL_DATADIR}/python-runtime
  FILES_MATCHING PATTERN "*.py"
  PATTERN "__pycache__" EXCLUDE)
# DREAM's rps for unmodified Robotarium scripts (dream run SCRIPT.py), beside the runtime it loads.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/python/rps_dream
  DESTINATION ${DREAM_INSTALL_DATADIR}/python-runtime
  FILES_MATCHING PATTERN "*.py"
  PATTERN "__pycache__" EXCLUDE)
install(FILES ${DREAM_BRIDGE_PYTHON_DIR}/run_submission.py DESTINATION ${DREAM_INSTALL_DATADIR}/bridge)
install(DIRECTORY ${DREAM_BRIDGE_PYTHON_DIR}/standin
  DESTINATION ${DREAM_INSTALL_DATADIR}/bridge
  FILES_MATCHING PATTERN "*.py"
  PATTERN "__pycache__" EXCLUDE)

# The CMake package.
install(EXPORT dreamTargets NAMESPACE dream:: DESTINATION ${DREAM_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/dreamConfig.cmake.in
  ${PROJECT_BINARY_DIR}/dreamConfig.cmake
  INSTALL_DESTINATION ${DREAM_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_BINDIR DREAM_INSTALL_DATADIR)
# Same minor version: the plugin API and the libraries' soname change with it before 1.0.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dreamConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/dreamConfig.cmake ${PROJECT_BINARY_DIR}/dreamConfigVersion.cmake
  DESTINATION ${DREAM_INSTALL_CMAKEDIR})
