# cmake/test_check_internal_includes.cmake: the include check must catch
# offenders.  Builds a small tree under WORK with one allowed and two
# forbidden includes of an *_internal.h header and a header with marked and
# unmarked declarations, runs
# check_internal_includes.cmake on it and fails unless exactly the
# forbidden ones are reported.
#   cmake -DWORK=DIR -DCHECK=cmake/check_internal_includes.cmake -P this file
file(REMOVE_RECURSE ${WORK})
file(WRITE ${WORK}/tests/test_got_extra.c "#include \"got_internal.h\"\n")
file(WRITE ${WORK}/tests/test_census.c "#include \"quadvec_internal.h\"\n")
file(WRITE ${WORK}/cli/cmd_x.c "  #  include \"lot_internal.h\"\n")
file(WRITE ${WORK}/cli/cmd_y.c "#include \"mesh.h\"\n")          # a private header
file(WRITE ${WORK}/tests/test_lot_mesh.c "#include \"mesh.h\"\n")   # its own tests
file(WRITE ${WORK}/lot/mesh.h "FLIPLAB_INTERNAL int lot_ok(void);\nint lot_private_unmarked(void);\n")
file(WRITE ${WORK}/got/got_internal.h
     "FLIPLAB_INTERNAL int got_marked(void);\nFLIPLAB_INTERNAL\nint got_marked_too(int a,\n"
     "                  int b);\nstatic inline int got_inline(void) { return 0; }\n"
     "int got_unmarked(void);\nconst char *got_unmarked_name(int k);\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${WORK} -DPRIVATE_HEADERS=lot/mesh.h,lot/order.h
                        -P ${CHECK}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "the check passed a tree with forbidden includes")
endif()
foreach(want "tests/test_census.c" "cli/cmd_x.c" "got_unmarked\n" "got_unmarked_name"
        "cli/cmd_y.c" "lot_private_unmarked")
  string(FIND "${all}" "${want}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the check did not name ${want}:\n${all}")
  endif()
endforeach()
foreach(wrong "test_got_extra.c" "got_marked" "got_inline" "test_lot_mesh.c" "lot_ok")
  string(FIND "${all}" "${wrong}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "the check refused ${wrong}, which is allowed:\n${all}")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
