# cmake/test_check_internal_includes.cmake: the include check must catch
# offenders.  Builds a small tree under WORK with one allowed and two
# forbidden includes of an *_internal.h header, runs
# check_internal_includes.cmake on it and fails unless exactly the two
# forbidden ones are reported.
#   cmake -DWORK=DIR -DCHECK=cmake/check_internal_includes.cmake -P this file
file(REMOVE_RECURSE ${WORK})
file(WRITE ${WORK}/tests/test_got_extra.c "#include \"got_internal.h\"\n")
file(WRITE ${WORK}/tests/test_census.c "#include \"quadvec_internal.h\"\n")
file(WRITE ${WORK}/cli/cmd_x.c "  #  include \"lot_internal.h\"\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -P ${CHECK}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "the check passed a tree with forbidden includes")
endif()
foreach(want "tests/test_census.c" "cli/cmd_x.c")
  string(FIND "${all}" "${want}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the check did not name ${want}:\n${all}")
  endif()
endforeach()
string(FIND "${all}" "test_got_extra.c" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "the check refused got's own test:\n${all}")
endif()
file(REMOVE_RECURSE ${WORK})
