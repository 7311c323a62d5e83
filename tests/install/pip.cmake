# `pip install .` into a fresh virtual environment with the system's site packages (numpy from
# Debian), then `import puncture` from another folder and the paper's default case solved.
# The extension is built in the project's own build tree (PUNCTURE_BUILD_DIR): this checks the
# packaging (pyproject.toml, setup.py, the package's files), not a second full build.
#   cmake -DSOURCE_DIR=.. -DBUILD_DIR=.. -DWORK_DIR=.. -DPYTHON=.. -DEXE=<puncture> -DVERSION=..
#         -P pip.cmake
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
# (No ';' in a script given to run: CMake would split the argument there.)
function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nexit ${rc}\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()
run(${PYTHON} -m venv --system-site-packages ${WORK_DIR}/venv)
set(ENV{PUNCTURE_BUILD_DIR} ${BUILD_DIR})
run(${WORK_DIR}/venv/bin/python -m pip install --no-build-isolation --no-deps --no-index
    --quiet ${SOURCE_DIR})
# The installed module's version, and its puncture force for the paper's default case against the
# CLI's (the same library: equal to the printed digits, 1e-12).
run(${WORK_DIR}/venv/bin/python -c
    "import puncture\np = puncture.predict_puncture(puncture.Problem())\nprint(puncture.__version__, repr(p.force_n), puncture.__file__)")
message(STATUS "${out}")
string(REGEX MATCH "^([0-9.]+) ([0-9.eE+-]+) (.*)" match "${out}")
set(python_force ${CMAKE_MATCH_2})  # before another MATCHES clears it
if(NOT CMAKE_MATCH_1 STREQUAL "${VERSION}")
  message(FATAL_ERROR "installed version '${CMAKE_MATCH_1}', expected '${VERSION}'")
endif()
if(NOT CMAKE_MATCH_3 MATCHES "^${WORK_DIR}/venv/")
  message(FATAL_ERROR "imported ${CMAKE_MATCH_3}, not the virtual environment's copy")
endif()
run(${EXE} puncture --format json)
string(JSON cli_force GET "${out}" puncture force_n)
# CMake has no floating point: Python compares.
run(${WORK_DIR}/venv/bin/python -c
    "import sys\na, b = ${python_force}, ${cli_force}\nsys.exit(abs(a - b) > 1e-12 * abs(b))")
