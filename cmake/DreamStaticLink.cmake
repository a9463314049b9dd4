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
  _dream_link_closure(${library} dream_libraries other_libraries)
  set(archives)
  foreach(dream_library IN LISTS dream_libraries)
    get_target_property(type ${dream_library} TYPE)
    if(type STREQUAL "SHARED_LIBRARY" OR type STREQUAL "STATIC_LIBRARY")
      if(NOT TARGET ${dream_library}_archive)
        add_library(${dream_library}_archive STATIC EXCLUDE_FROM_ALL $<TARGET_OBJECTS:${dream_library}>)
        set_target_properties(${dream_library}_archive PROPERTIES LINKER_LANGUAGE CXX)
      endif()
      list(APPEND archives ${dream_library}_archive)
    endif()
  endforeach()
  # What the library's headers need to compile against (include folders,
  # definitions), without its link items.
  target_include_directories(${executable} PRIVATE $<TARGET_PROPERTY:${library},INTERFACE_INCLUDE_DIRECTORIES>)
  target_compile_definitions(${executable} PRIVATE $<TARGET_PROPERTY:${library},INTERFACE_COMPILE_DEFINITIONS>)
  target_link_libraries(${executable} PRIVATE "$<LINK_GROUP:RESCAN,${archives}>" ${other_libraries})
  target_link_options(${executable} PRIVATE LINKER:--gc-sections LINKER:--as-needed)
  # No dream library is loaded from a folder: nothing to search.
  set_target_properties(${executable} PROPERTIES SKIP_BUILD_RPATH ON INSTALL_RPATH "")
endfunction()

# The link closure of <target>: the dream libraries (targets named dream_*)
# in <dream_out>, everything else they link (imported targets, files, flags)
# in <other_out>.
function(_dream_link_closure target dream_out other_out)
  set(queue ${target})
  set(dream_libraries)
  set(others)
  while(queue)
    list(POP_FRONT queue item)
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
      if(item IN_LIST dream_libraries)
        continue()
      endif()
      list(APPEND dream_libraries ${item})
      foreach(property LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
        get_target_property(links ${item} ${property})
        if(links)
          list(APPEND queue ${links})
        endif()
      endforeach()
    elseif(NOT item IN_LIST others)
      list(APPEND others ${item})
    endif()
  endwhile()
  set(${dream_out} ${dream_libraries} PARENT_SCOPE)
  set(${other_out} ${others} PARENT_SCOPE)
endfunction()
