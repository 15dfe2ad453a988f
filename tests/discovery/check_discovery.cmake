# Guards the registration of the Catch2 tests with ctest (tests/CMakeLists.txt).
# Run with cmake -P:
#   MODE=counts: for each executable in EXECUTABLES (";"-separated paths,
#     passed with "|" instead of ";"), the number of ctest tests named
#     "<stem>: …" must equal the number of Catch2 test cases it lists, and no
#     test case name may contain ';' (CMake's discovery splits such a name in
#     two halves that match nothing).
#   MODE=unmatched: an executable run with a test name that matches nothing
#     must fail (exit code 2 under --warn NoTests), so a test that silently
#     did not run fails the suite.
cmake_minimum_required(VERSION 3.20)

if(MODE STREQUAL "unmatched")
  execute_process(COMMAND "${EXECUTABLE}" "no test case has this name" --warn NoTests
                  RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET)
  if(NOT code EQUAL 2)
    message(FATAL_ERROR "a run that matches no test case exited with '${code}', expected 2")
  endif()
  return()
endif()

execute_process(COMMAND "${CTEST}" -N --test-dir "${BUILD_DIR}"
                OUTPUT_VARIABLE listing RESULT_VARIABLE code)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "ctest -N failed with '${code}'")
endif()
string(REPLACE "|" ";" executables "${EXECUTABLES}")
set(problems "")
foreach(executable IN LISTS executables)
  get_filename_component(stem "${executable}" NAME_WE)
  execute_process(COMMAND "${executable}" --list-test-names-only
                  OUTPUT_VARIABLE names RESULT_VARIABLE code)
  # --list-test-names-only exits with the number of names listed.
  string(REGEX MATCHALL "[^\n]+" lines "${names}")
  set(cases 0)
  foreach(line IN LISTS lines)
    math(EXPR cases "${cases} + 1")
  endforeach()
  # A ';' inside a listed name splits that line into list items above; count
  # the separators in the raw text instead of trusting the item count.
  string(FIND "${names}" ";" semicolon)
  if(NOT semicolon EQUAL -1)
    string(SUBSTRING "${names}" ${semicolon} 80 around)
    list(APPEND problems "${stem}: a test case name contains ';' (near '${around}')")
  endif()
  string(REGEX MATCHALL "Test +#[0-9]+: ${stem}:[^\n]*" registered "${listing}")
  list(LENGTH registered tests)
  if(NOT cases EQUAL tests)
    list(APPEND problems "${stem}: ${cases} Catch2 test cases, ${tests} ctest tests")
  endif()
  if(cases EQUAL 0)
    list(APPEND problems "${stem}: lists no test case")
  endif()
  message(STATUS "${stem}: ${cases} Catch2 test cases, ${tests} ctest tests")
endforeach()
if(problems)
  string(REPLACE ";" "\n  " text "${problems}")
  message(FATAL_ERROR "test registration is broken:\n  ${text}")
endif()
