# Runs an example with bad command lines (-DEXE=path -DNAME=program): each must
# exit with status 2 and print the problem and a usage line on stderr; --help
# must print the usage line on stdout and exit 0.
foreach(args "--dt;abc" "--dt" "--bogus;1" "--dt;0.5x")
  execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 2)
    message(FATAL_ERROR "${NAME} ${args}: exit status ${status}, expected 2\n${out}${err}")
  endif()
  if(NOT err MATCHES "^${NAME}: .*\nusage: ${NAME} \\[--out DIR\\]")
    message(FATAL_ERROR "${NAME} ${args}: no message and usage line on stderr:\n${err}")
  endif()
endforeach()
# --help and -h: the usage line on stdout, status 0 (as the Python examples).
foreach(args "--help" "-h")
  execute_process(COMMAND ${EXE} ${args} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0 OR NOT out MATCHES "^usage: ${NAME} \\[--out DIR\\]")
    message(FATAL_ERROR "${NAME} ${args}: exit status ${status}, expected 0 and the usage line on stdout\n${out}${err}")
  endif()
endforeach()
