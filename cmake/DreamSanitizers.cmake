# DREAM_SANITIZE: sanitizers for a checking build (issue 10 item 7), e.g.
#   cmake -S . -B build-asan -DDREAM_SANITIZE=address,undefined   (or: cmake --preset asan)
# Empty (the default) leaves the flags alone, so a Release build is unchanged.
# Every target, libraries included, is instrumented: a bad access in a library
# called by a test is caught where it happens, not where the test looks.
if(DREAM_SANITIZE)
  if(NOT DREAM_SANITIZE MATCHES "^[a-z,-]+$")
    message(FATAL_ERROR "DREAM_SANITIZE must be a comma-separated list such as address,undefined; got '${DREAM_SANITIZE}'")
  endif()
  # Frame pointers give whole stacks in the reports; no recovery, so the
  # first undefined behaviour fails the test that met it.
  add_compile_options(-fsanitize=${DREAM_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${DREAM_SANITIZE})
  message(STATUS "dream: sanitizers ${DREAM_SANITIZE}")
endif()
