# One malformed scene (tests/scenes/malformed/*.toml): `firn run` must exit with status 2, print
# exactly one line on standard error that names the key given in the file's "# expect: KEY"
# header, and write nothing (no output folder, so certainly no `ok` summary).
# Usage: cmake -DFIRN=path/to/firn -DSCENE=file.toml -DOUT=scratch/folder -P malformed_scene.cmake
file(STRINGS "${SCENE}" header LIMIT_COUNT 1)
string(REGEX REPLACE "^# expect: " "" expected "${header}")
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${FIRN}" run "${SCENE}" --out "${OUT}" RESULT_VARIABLE status ERROR_VARIABLE err
                OUTPUT_VARIABLE out)
if(NOT status EQUAL 2)
  message(FATAL_ERROR "exit status ${status}, expected 2; stderr: ${err}")
endif()
string(STRIP "${err}" err)
string(FIND "${err}" "\n" newline)
if(NOT newline EQUAL -1)
  message(FATAL_ERROR "more than one line on standard error:\n${err}")
endif()
string(FIND "${err}" "${expected}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the message does not name '${expected}': ${err}")
endif()
if(EXISTS "${OUT}")
  message(FATAL_ERROR "${OUT} was written")
endif()
message(STATUS "${err}")
