# `gcx expand PROGRAM --to nct [ARGS]` must exit 0 and print exactly the EXPECTED file.
execute_process(COMMAND ${GCX} expand ${PROGRAM} --to nct ${ARGS} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "exit code ${rc}\n${err}")
endif()
file(READ ${EXPECTED} expected)
if(NOT out STREQUAL expected)
  message(FATAL_ERROR "output differs from ${EXPECTED}:\n${out}")
endif()
