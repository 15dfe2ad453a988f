# cmake -P script: install sinew, build the downstream example against the
# installed tree only, run it; check that no installed header needs a private
# dependency. Any failing step fails the test.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")

function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "step failed (${code}): ${ARGN}\n${out}\n${err}")
  endif()
  message("${out}")
endfunction()

step(${CMAKE_COMMAND} --install "${SINEW_BUILD_DIR}" --prefix "${prefix}")
# The library links nlohmann_json privately: no installed header may need it.
file(GLOB_RECURSE installed_headers "${prefix}/include/sinew/*.hpp")
if(NOT installed_headers)
  message(FATAL_ERROR "no headers installed under ${prefix}/include/sinew")
endif()
foreach(header ${installed_headers})
  file(READ "${header}" text)
  if(text MATCHES "#include <nlohmann/")
    message(FATAL_ERROR "installed header ${header} includes nlohmann/json, a private dependency")
  endif()
endforeach()
step(${CMAKE_COMMAND} -S "${DOWNSTREAM_SOURCE}" -B "${WORK_DIR}/build"
     -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
step(${CMAKE_COMMAND} --build "${WORK_DIR}/build")
step("${WORK_DIR}/build/circle_fit")
