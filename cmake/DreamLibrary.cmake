include_guard(GLOBAL)
include(DreamWarnings)

# dream_add_library(<name> <source>...): the library dream_<name>, known as
# dream::<name>, whose include/ folder (beside the calling CMakeLists.txt) is
# its public headers, built with the project's warnings. Dependencies and any
# other settings stay with the caller.
function(dream_add_library name)
  add_library(dream_${name} ${ARGN})
  add_library(dream::${name} ALIAS dream_${name})
  target_include_directories(dream_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  dream_set_warnings(dream_${name})
endfunction()
