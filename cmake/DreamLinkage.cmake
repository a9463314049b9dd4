# The dream libraries are shared libraries, so the tools and the controller
# plugins they dlopen share one copy of the dream code: one ControllerRegistry,
# one vtable and type_info per class. Installed tools and libraries find each
# other relative to themselves ($ORIGIN), so an install prefix can be moved;
# in the build tree CMake's build RPATH points at the build folders.
option(BUILD_SHARED_LIBS "Build the dream libraries as shared libraries (controller plugins need it)" ON)
include(GNUInstallDirs)
file(RELATIVE_PATH DREAM_BIN_TO_LIB ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_LIBDIR})
set(CMAKE_INSTALL_RPATH "$ORIGIN/${DREAM_BIN_TO_LIB};$ORIGIN")
# Where an installed dream finds its data files (the types jar, the bridge's
# Python files): share/dream, relative to bin.
file(RELATIVE_PATH DREAM_BIN_TO_DATA ${CMAKE_INSTALL_FULL_BINDIR} ${CMAKE_INSTALL_FULL_DATADIR}/dream)
if(BUILD_SHARED_LIBS)
  # Calls within a library may still be inlined and bound directly, as in a
  # static build (GCC otherwise treats every exported function as replaceable).
  add_compile_options(-fno-semantic-interposition)
endif()

# dream_library_version(<targets...>): the project's version on shared
# libraries; the soname carries major.minor, as the API is not stable before 1.0.
function(dream_library_version)
  set_target_properties(${ARGN} PROPERTIES
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
endfunction()
