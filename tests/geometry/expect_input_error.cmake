# Runs `ellc geometry POSES` and requires exit code 2 and a message naming the bad key.
execute_process(COMMAND ${COMMAND} geometry ${POSES} RESULT_VARIABLE code ERROR_VARIABLE message OUTPUT_QUIET)
if(NOT code EQUAL 2)
  message(FATAL_ERROR "expected exit code 2, got ${code}: ${message}")
endif()
if(NOT message MATCHES "unknown key 'body_J\\.positon'")
  message(FATAL_ERROR "the message does not name the key: ${message}")
endif()
