# Runs the puncture CLI once and checks its exit code and output.
#   cmake -DEXE=<puncture> [-DEXPECT_RC=0] [-DSTDOUT_REGEX=..] [-DSTDOUT_REGEX2=..]
#         [-DSTDOUT_REGEX3=..] [-DSTDERR_REGEX=..] [-DJSON_KEYS="a.b c.0.d"]
#         [-DJSON_NULL="a.b"] [-DOUTPUT_FILE=<file the CLI writes with -o>]
#         -P run_cli.cmake -- <arguments of puncture>
# A successful run must print no NaN or infinity; a failing one must print nothing on stdout
# (with --format json: only {"error": {status, failure_kind, message}}) and a message on stderr.
cmake_minimum_required(VERSION 3.21)

set(args)
set(collect OFF)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
  if(collect)
    list(APPEND args "${CMAKE_ARGV${i}}")
  elseif("${CMAKE_ARGV${i}}" STREQUAL "--")
    set(collect ON)
  endif()
endforeach()
if(NOT DEFINED EXPECT_RC OR EXPECT_RC STREQUAL "")
  set(EXPECT_RC 0)
endif()
if(OUTPUT_FILE)
  file(REMOVE "${OUTPUT_FILE}" "${OUTPUT_FILE}.part" "${OUTPUT_FILE}.part.spec")  # sweep's
endif()

execute_process(COMMAND "${EXE}" ${args}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REPLACE ";" " " shown "${args}")

function(fail why)
  message(FATAL_ERROR "puncture ${shown}\n${why}\n--- exit code: ${rc}\n--- stdout:\n${out}\n"
                      "--- stderr:\n${err}")
endfunction()

if(NOT rc STREQUAL "${EXPECT_RC}")
  fail("expected exit code ${EXPECT_RC}")
endif()

if(NOT EXPECT_RC EQUAL 0)
  # Nothing on stdout, except the error document that --format json asks for.
  if(NOT out STREQUAL "" AND NOT out MATCHES "^{\n  \"error\": {")
    fail("a failing run must print nothing on stdout but a JSON error document")
  endif()
  if(err STREQUAL "")
    fail("a failing run must explain itself on stderr")
  endif()
endif()
if(STDERR_REGEX AND NOT err MATCHES "${STDERR_REGEX}")
  fail("stderr does not match: ${STDERR_REGEX}")
endif()

if(OUTPUT_FILE)
  if(NOT out STREQUAL "")
    fail("with --output nothing goes to stdout")
  endif()
  if(NOT EXISTS "${OUTPUT_FILE}")
    fail("no output file ${OUTPUT_FILE}")
  endif()
  file(READ "${OUTPUT_FILE}" out)
endif()

foreach(var STDOUT_REGEX STDOUT_REGEX2 STDOUT_REGEX3)
  if(${var} AND NOT out MATCHES "${${var}}")
    fail("output does not match: ${${var}}")
  endif()
endforeach()

# No NaN or infinity anywhere in a result (words such as 'information' are fine).
set(letter "A-Za-z_")
if(out MATCHES "(^|[^${letter}])([Nn][Aa][Nn]|[Ii][Nn][Ff]|[Ii][Nn][Ff][Ii][Nn][Ii][Tt][Yy])([^${letter}]|$)")
  fail("the output contains NaN or infinity: '${CMAKE_MATCH_0}'")
endif()

# JSON: the document parses and holds the given paths (dot-separated, array indices as numbers).
macro(json_type path)
  string(REPLACE "." ";" parts "${path}")
  string(JSON type ERROR_VARIABLE json_error TYPE "${out}" ${parts})
  if(json_error)
    fail("JSON path ${path}: ${json_error}")
  endif()
endmacro()
separate_arguments(json_keys UNIX_COMMAND "${JSON_KEYS}")
foreach(path IN LISTS json_keys)
  json_type("${path}")
endforeach()
separate_arguments(json_nulls UNIX_COMMAND "${JSON_NULL}")
foreach(path IN LISTS json_nulls)
  json_type("${path}")
  if(NOT type STREQUAL "NULL")
    fail("JSON path ${path} should be null, is ${type}")
  endif()
endforeach()
