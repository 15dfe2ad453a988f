# Sanitizer and fuzzing build (scripts/sanitize_and_fuzz.sh, docs/fuzzing.md).
#
# SINEW_SANITIZE: AddressSanitizer and UndefinedBehaviorSanitizer on every
# target, compile and link; any UB report aborts (no recovery), so a ctest run
# fails on it.
#
# SINEW_FUZZ: libFuzzer targets in fuzz/. Needs Clang. Only the code under test,
# the sinew library, gets coverage instrumentation (-fsanitize=fuzzer-no-link,
# added in fuzz/CMakeLists.txt); the fuzz executables link libFuzzer
# (-fsanitize=fuzzer). The other executables (tests, CLI) link the instrumented
# library too: its coverage callbacks are then the sanitizer runtime's no-op
# defaults, which is why SINEW_FUZZ needs SINEW_SANITIZE.
#
# Included before any target is defined, so that add_compile_options and
# add_link_options reach all of them.

if(SINEW_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR
      "SINEW_FUZZ=ON needs Clang (libFuzzer); the C++ compiler is ${CMAKE_CXX_COMPILER_ID} "
      "${CMAKE_CXX_COMPILER_VERSION}. Configure a fresh build folder with CC=clang-14 CXX=clang++-14 "
      "(scripts/sanitize_and_fuzz.sh does), or set SINEW_FUZZ=OFF.")
  endif()
  if(NOT SINEW_SANITIZE)
    message(FATAL_ERROR
      "SINEW_FUZZ=ON needs SINEW_SANITIZE=ON: the coverage callbacks of the instrumented sinew library "
      "come from the sanitizer runtime that every executable (tests, CLI) then links.")
  endif()
endif()

if(SINEW_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang|GNU")
    message(FATAL_ERROR "SINEW_SANITIZE=ON needs Clang or GCC; the C++ compiler is ${CMAKE_CXX_COMPILER_ID}.")
  endif()
  set(SINEW_SANITIZER_FLAGS -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  add_compile_options(${SINEW_SANITIZER_FLAGS})
  add_link_options(${SINEW_SANITIZER_FLAGS})
  # An installed sanitized libsinew needs the sanitizer runtime in every program
  # that links it (tests/downstream builds one): the exported target says so.
  # Deferred to the end of this directory, where the target sinew exists.
  cmake_language(DEFER CALL target_link_options sinew INTERFACE "$<INSTALL_INTERFACE:-fsanitize=address,undefined>")
endif()
