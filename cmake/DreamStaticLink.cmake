include_guard(GLOBAL)

# dream_link_dream_statically(<executable> <library>): links <executable> with
# <library> and everything it needs, but the dream shared libraries among them
# as static archives of the very same objects (no second compilation), so the
# program maps none of them. An agent process maps two dozen libraries
# otherwise, and each costs resident memory whatever the process uses of it
# (the kernel's fault-around fills 64 KB around every page touched at
# start-up; docs/performance.md, "Agent memory"). The other libraries
# (spdlog, yaml-cpp, LCM, the C++ runtime) stay shared; only what is used of
# the archives is linked (--gc-sections drops the rest).
#
# A program linked so holds its own copy of the dream code: a library that
# links the shared dream libraries (a controller plugin, the embedded Python
# module) must not be loaded into it, or two copies of ControllerRegistry and
# the classes would meet.
function(dream_link_dream_statically executable library)
  _dream_archive_of(${library} archive)
  # What the library's headers need to compile against (include folders,
  # definitions), without its link items.
  target_include_directories(${executable} PRIVATE $<TARGET_PROPERTY:${library},INTERFACE_INCLUDE_DIRECTORIES>)
  target_compile_definitions(${executable} PRIVATE $<TARGET_PROPERTY:${library},INTERFACE_COMPILE_DEFINITIONS>)
  target_link_libraries(${executable} PRIVATE ${archive})
  target_link_options(${executable} PRIVATE LINKER:--gc-sections LINKER:--as-needed)
  # No dream library is loaded from a folder: nothing to search.
  set_target_properties(${executable} PROPERTIES SKIP_BUILD_RPATH ON INSTALL_RPATH "")
endfunction()

# <target>_archive, made once: a static archive of <target>'s objects (an
# interface library for a dream target without objects) that links what
# <target> links, its dream libraries replaced by their archives, so CMake
# orders the archives on the link line as it orders the libraries.
function(_dream_archive_of target out)
  get_target_property(aliased ${target} ALIASED_TARGET)
  if(aliased)
    set(target ${aliased})
  endif()
  set(archive ${target}_archive)
  set(${out} ${archive} PARENT_SCOPE)
  if(TARGET ${archive})
    return()
  endif()
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "SHARED_LIBRARY" OR type STREQUAL "STATIC_LIBRARY")
    add_library(${archive} STATIC EXCLUDE_FROM_ALL $<TARGET_OBJECTS:${target}>)
    set_target_properties(${archive} PROPERTIES LINKER_LANGUAGE CXX)
  else()
    add_library(${archive} INTERFACE)
  endif()
  set(links)
  foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
    get_target_property(items ${target} ${property})
    if(NOT items)
      continue()
    endif()
    foreach(item IN LISTS items)
      if(item MATCHES "^\\$<LINK_ONLY:(.*)>$")
        set(item ${CMAKE_MATCH_1})
      endif()
      if(TARGET ${item})
        get_target_property(aliased ${item} ALIASED_TARGET)
        if(aliased)
          set(item ${aliased})
        endif()
      endif()
      if(TARGET ${item} AND item MATCHES "^dream_")
        _dream_archive_of(${item} item)
      endif()
      if(NOT item IN_LIST links)
        list(APPEND links ${item})
      endif()
    endforeach()
  endforeach()
  target_link_libraries(${archive} INTERFACE ${links})
endfunction()
