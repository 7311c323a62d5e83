# Installs the build into WORK_DIR/prefix, builds examples/consumer against it with
# find_package(puncture) and runs it, and runs the installed CLI: its --help, the default puncture
# point, and --plot with a stand-in interpreter that records which plotting script it was given
# (the installed copy, not the source tree's).
#   cmake -DBUILD_DIR=.. -DCONFIG=.. -DWORK_DIR=.. -DCONSUMER_SOURCE_DIR=.. -DCXX_COMPILER=..
#         -P install.cmake
cmake_minimum_required(VERSION 3.21)

set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

set(config_args)
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} ${config_args})
foreach(file bin/puncture include/puncture/loading_curve.hpp)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${prefix}/${file}")
  endif()
endforeach()
file(GLOB_RECURSE config_files ${prefix}/*/punctureConfig.cmake)
file(GLOB_RECURSE plot_scripts ${prefix}/*/plot_cli.py)
if(NOT config_files OR NOT plot_scripts)
  message(FATAL_ERROR "not installed: punctureConfig.cmake or plot_cli.py under ${prefix}")
endif()

# A consumer project of its own, found through CMAKE_PREFIX_PATH alone.
run("configuring examples/consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${consumer_build}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
run("building examples/consumer" ${CMAKE_COMMAND} --build ${consumer_build} --config Release)
find_program(consumer puncture_consumer PATHS ${consumer_build} ${consumer_build}/Release
             NO_DEFAULT_PATH REQUIRED)
run("the consumer" ${consumer})
if(NOT out MATCHES "puncture at F = 0\\.699[0-9]* N")
  message(FATAL_ERROR "the consumer printed an unexpected result:\n${out}")
endif()
message(STATUS "consumer: ${out}")

# The installed CLI.
run("puncture --help" ${prefix}/bin/puncture --help)
if(NOT out MATCHES "puncture")
  message(FATAL_ERROR "puncture --help printed no help:\n${out}")
endif()
run("puncture puncture" ${prefix}/bin/puncture puncture)
if(NOT out MATCHES "puncture force +0\\.699[0-9]* N")
  message(FATAL_ERROR "the installed puncture printed an unexpected result:\n${out}")
endif()

# --plot runs the installed plotting script: a stand-in interpreter records its arguments
# (-B SCRIPT KIND DATA TARGET).
set(fake_python ${WORK_DIR}/fake-python)
file(WRITE ${fake_python} "#!/bin/sh\nprintf '%s\\n' \"$2\" > '${WORK_DIR}/plot-script.txt'\n")
file(CHMOD ${fake_python} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
run("puncture curve --plot" ${CMAKE_COMMAND} -E env PUNCTURE_PYTHON=${fake_python}
    --unset=PUNCTURE_PLOT_SCRIPT ${prefix}/bin/puncture curve --points 5 --plot ${WORK_DIR}/c.png)
file(READ ${WORK_DIR}/plot-script.txt script)
string(STRIP "${script}" script)
file(REAL_PATH ${prefix} real_prefix)
string(FIND "${script}" "${real_prefix}/" at)
if(NOT at EQUAL 0 OR NOT script MATCHES "/puncture/plot_cli\\.py$" OR NOT EXISTS "${script}")
  message(FATAL_ERROR "the installed puncture ran the plotting script '${script}', not the one "
                      "installed under ${real_prefix}")
endif()
message(STATUS "installed CLI runs ${script}")
