# Runs one bad-input case: cmake -DSINEW=<sinew> -DCASE=<name.case> -DSCRATCH=<folder> -P run_case.cmake
#
# A case file (cases/<name>.case) holds "key: value" lines; '#' starts a
# comment line:
#   args:        the sinew arguments, split like a POSIX shell would; @CASE@ is
#                the case's data folder cases/<name>/, @OUT@ the scratch folder
#   exit:        the expected exit code (2: bad input)
#   message:     a CMake regular expression the one stderr line must match
#   preexisting: optional; a file under @OUT@ created before the run that must
#                be byte-identical afterwards (nothing truncated or rewritten)
#   max_length:  optional; the longest accepted message, counted with the case
#                and scratch folders written as @CASE@ and @OUT@
#
# sinew runs in the scratch folder (emptied first), so anything it writes to
# its working directory counts as written. Checks: the exit code; stdout is
# empty; stderr is exactly one line ending in one newline, starting with
# "sinew: " and matching the message; the preexisting file is unchanged; and,
# when the expected exit code is 2, no file or folder appeared under @OUT@ (nor
# in the case's folder).
cmake_minimum_required(VERSION 3.16)

foreach(required SINEW CASE SCRATCH)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "run_case.cmake needs -D${required}=...")
  endif()
endforeach()

include("${CMAKE_CURRENT_LIST_DIR}/parse_case.cmake")
sinew_parse_case("${CASE}" case)
if(NOT case_error STREQUAL "")
  message(FATAL_ERROR "${case_error}")
endif()
foreach(key args exit message)
  if(NOT case_has_${key})
    message(FATAL_ERROR "${CASE}: missing '${key}:'")
  endif()
endforeach()

get_filename_component(case_name "${CASE}" NAME_WE)
get_filename_component(case_folder "${CASE}" DIRECTORY)
set(case_dir "${case_folder}/${case_name}")

file(REMOVE_RECURSE "${SCRATCH}")
file(MAKE_DIRECTORY "${SCRATCH}")

set(preexisting_content "preexisting content: must survive a bad-input run unchanged\n")
if(case_has_preexisting)
  set(preexisting_path "${SCRATCH}/${case_preexisting}")
  get_filename_component(preexisting_parent "${preexisting_path}" DIRECTORY)
  file(MAKE_DIRECTORY "${preexisting_parent}")
  file(WRITE "${preexisting_path}" "${preexisting_content}")
endif()
file(GLOB_RECURSE files_before LIST_DIRECTORIES true RELATIVE "${SCRATCH}" "${SCRATCH}/*")

# Quoted, so that folders with spaces stay one argument ("dir"/scene.json is one word).
string(REPLACE "@CASE@" "\"${case_dir}\"" args "${case_args}")
string(REPLACE "@OUT@" "\"${SCRATCH}\"" args "${args}")
separate_arguments(arg_list UNIX_COMMAND "${args}")
file(GLOB_RECURSE case_files_before LIST_DIRECTORIES true "${case_dir}/*")

execute_process(
  COMMAND "${SINEW}" ${arg_list}
  WORKING_DIRECTORY "${SCRATCH}"
  RESULT_VARIABLE got_exit
  OUTPUT_VARIABLE got_out
  ERROR_VARIABLE got_err
  TIMEOUT 60)

set(problems "")
macro(problem text)
  string(APPEND problems "\n  - ${text}")
endmacro()

if(NOT "${got_exit}" STREQUAL "${case_exit}")
  problem("exit code: expected ${case_exit}, got ${got_exit}")
endif()
if(NOT got_out STREQUAL "")
  string(LENGTH "${got_out}" out_length)
  string(SUBSTRING "${got_out}" 0 1500 out_start)
  problem("stdout: expected nothing, got ${out_length} characters, starting:\n${out_start}")
endif()

string(LENGTH "${got_err}" err_length)
string(REGEX MATCHALL "\n" newlines "${got_err}")
list(LENGTH newlines newline_count)
if(err_length EQUAL 0)
  problem("stderr: expected one line, got nothing")
elseif(NOT newline_count EQUAL 1 OR NOT got_err MATCHES "\n$")
  problem("stderr: expected exactly one line ending in a newline, got ${newline_count} newline(s):\n${got_err}")
else()
  string(REGEX REPLACE "\n$" "" line "${got_err}")
  if(NOT line MATCHES "^sinew: ")
    problem("stderr: expected the line to start with 'sinew: ', got: ${line}")
  endif()
  if(NOT line MATCHES "${case_message}")
    problem("stderr: expected a line matching\n      ${case_message}\n    got\n      ${line}")
  endif()
  if(case_has_max_length)
    string(REPLACE "${case_dir}" "@CASE@" short "${line}")
    string(REPLACE "${SCRATCH}" "@OUT@" short "${short}")
    string(LENGTH "${short}" short_length)
    if(short_length GREATER case_max_length)
      problem("stderr: expected at most ${case_max_length} characters (paths as @CASE@/@OUT@), got ${short_length}")
    endif()
  endif()
endif()

if(case_has_preexisting)
  if(NOT EXISTS "${preexisting_path}")
    problem("${case_preexisting}: existed before the run, gone after it")
  else()
    file(READ "${preexisting_path}" preexisting_after)
    if(NOT preexisting_after STREQUAL preexisting_content)
      string(LENGTH "${preexisting_after}" after_length)
      problem("${case_preexisting}: changed by the run (now ${after_length} bytes)")
    endif()
  endif()
endif()

if("${case_exit}" STREQUAL "2")
  file(GLOB_RECURSE files_after LIST_DIRECTORIES true RELATIVE "${SCRATCH}" "${SCRATCH}/*")
  list(REMOVE_ITEM files_after ${files_before} "")
  if(files_after)
    string(REPLACE ";" ", " created "${files_after}")
    problem("@OUT@: expected nothing written on bad input, found new: ${created}")
  endif()
endif()

# The case's own folder is input: a run must not write into the source tree.
file(GLOB_RECURSE case_files_after LIST_DIRECTORIES true "${case_dir}/*")
if(NOT case_files_after STREQUAL case_files_before)
  problem("@CASE@: the run changed the files of the case's folder")
endif()

if(problems)
  message(FATAL_ERROR "bad input case ${case_name} failed\n  command: sinew ${args}\n  exit code: ${got_exit}\n"
                      "  stderr: ${got_err}${problems}")
endif()
message(STATUS "bad input case ${case_name}: exit ${got_exit}: ${line}")
file(REMOVE_RECURSE "${SCRATCH}")
