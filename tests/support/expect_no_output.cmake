# `gcx expand PROGRAM --to canonical -o OUT` must fail with exit 1 and leave no OUT behind.
file(REMOVE ${OUT})
execute_process(COMMAND ${GCX} expand ${PROGRAM} --to canonical -o ${OUT}
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "exit code ${rc}, expected 1\n${err}")
endif()
if(EXISTS ${OUT} OR EXISTS ${OUT}.gcx-tmp)
  message(FATAL_ERROR "partial output file left behind: ${OUT}")
endif()
