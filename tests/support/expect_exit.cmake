# Runs `GCX CMD FILE [ARGS]` and checks the exit code, a piece of standard error and one it
# must not have. STDOUT_FILE (optional) receives standard output, e.g. /dev/full to test a
# failing write.
if(DEFINED STDOUT_FILE)
  execute_process(COMMAND ${GCX} ${CMD} ${FILE} ${ARGS} RESULT_VARIABLE rc
                  OUTPUT_FILE ${STDOUT_FILE} ERROR_VARIABLE err)
  set(out "(to ${STDOUT_FILE})")
else()
  execute_process(COMMAND ${GCX} ${CMD} ${FILE} ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
endif()
if(NOT rc EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "exit code ${rc}, expected ${EXPECT_EXIT}\nstdout: ${out}\nstderr: ${err}")
endif()
if(DEFINED EXPECT_STDERR)
  string(FIND "${err}" "${EXPECT_STDERR}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "stderr lacks '${EXPECT_STDERR}':\n${err}")
  endif()
endif()
if(DEFINED EXPECT_NO_STDERR)
  string(FIND "${err}" "${EXPECT_NO_STDERR}" pos)
  if(NOT pos EQUAL -1)
    message(FATAL_ERROR "stderr has '${EXPECT_NO_STDERR}':\n${err}")
  endif()
endif()
