# cmake -P run.cmake: installs the built pendulum-g into a fresh prefix, then
# configures, builds and runs tests/consumer against it, as a user would.
# Variables: BUILD_DIR (pendulum-g's build), SOURCE_DIR (tests/consumer),
# WORK_DIR (scratch), GENERATOR, BUILD_TYPE, CXX_COMPILER, CXX_FLAGS,
# LINK_FLAGS (the sanitizer build's, empty otherwise).
function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "consumer test: ${step} failed (${rc}):\n${out}")
  endif()
  message(STATUS "${step}: ok")
  set(output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
run("configure" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -G ${GENERATOR}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
    "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}")
# The package must come from the prefix, not from a build tree or the system.
file(STRINGS ${build}/CMakeCache.txt found REGEX "^pendulum_DIR:")
if(NOT found MATCHES "=${prefix}/")
  message(FATAL_ERROR "consumer test: pendulum found elsewhere (${found}), expected under ${prefix}")
endif()
run("build" ${CMAKE_COMMAND} --build ${build})
run("run" ${build}/consumer)
message("${output}")
