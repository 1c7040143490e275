# cmake/check_internal_includes.cmake: the layering rule for the code
# outside the library.  The library's folders are object libraries whose
# headers only the folders above them see (CMakeLists.txt); cli/, bench/,
# tests/, fuzz/ and plugins/ see every header, so this scan keeps them off
# the *_internal.h headers, which are no interface:
#
#   cli/ and plugins/ include no *_internal.h at all;
#   tests/test_STEM[_MORE].c, bench/bench_STEM[_MORE].c and
#   fuzz/fuzz_STEM[_MORE].c are STEM's own tests and may include
#   STEM_internal.h (test_quadvec.c: quadvec_internal.h; test_got_poly.c:
#   got_internal.h); no other.
#
# Everything else a test needs goes through public verbs.  The scan also
# checks that every function of an *_internal.h header is marked
# FLIPLAB_INTERNAL (below).  Run as
#   cmake -DSOURCE_DIR=DIR [-DSTAMP=FILE] -P check_internal_includes.cmake
# Fails listing every offending include; on success touches STAMP.
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_internal_includes: set -DSOURCE_DIR")
endif()
set(offenders "")
foreach(dir cli plugins tests bench fuzz)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${dir}/*.c ${SOURCE_DIR}/${dir}/*.h
       ${SOURCE_DIR}/${dir}/*.cpp)
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<][^\">]*_internal\\.h[\">]")
    get_filename_component(name ${f} NAME)
    foreach(line ${lines})
      string(REGEX REPLACE ".*[\"</]([^\"</]*)_internal\\.h[\">].*" "\\1" stem "${line}")
      set(ok FALSE)
      if(dir MATCHES "^(tests|bench|fuzz)$")
        string(REGEX REPLACE "s$" "" kind ${dir})   # tests -> test
        if(name MATCHES "^${kind}_${stem}(_[A-Za-z0-9_]*)?\\.(c|cpp)$")
          set(ok TRUE)
        endif()
      endif()
      if(NOT ok)
        file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
        string(STRIP "${line}" line)
        list(APPEND offenders "  ${rel}: ${line}")
      endif()
    endforeach()
  endforeach()
endforeach()
set(report "")
if(offenders)
  string(REPLACE ";" "\n" text "${offenders}")
  string(APPEND report "an *_internal.h header included outside its own module "
         "(cmake/check_internal_includes.cmake says who may):\n${text}\n")
endif()

# And the other half of the rule: every function an *_internal.h header
# declares (a line at column 0 of the form TYPE name(, not static, inline,
# a typedef or a macro) carries FLIPLAB_INTERNAL (geom/fliplab_config.h),
# alone on the line before or in front, so a shared build exports none.
file(GLOB internal_headers ${SOURCE_DIR}/*/*_internal.h)
set(unmarked "")
foreach(h ${internal_headers})
  file(STRINGS ${h} lines)
  set(prev "")
  foreach(line IN LISTS lines)
    if(line MATCHES "^[A-Za-z_][A-Za-z_0-9 *]*[ *][a-z_][a-z_0-9]*\\("
       AND NOT line MATCHES "^(static|typedef|extern|FLIPLAB_INTERNAL|QUADVEC_INLINE|return)[ (]"
       AND NOT prev STREQUAL "FLIPLAB_INTERNAL")
      file(RELATIVE_PATH rel ${SOURCE_DIR} ${h})
      string(REGEX REPLACE "^.*[ *]([a-z_][a-z_0-9]*)\\(.*$" "\\1" name "${line}")
      list(APPEND unmarked "  ${rel}: ${name}")
    endif()
    set(prev "${line}")
  endforeach()
endforeach()
if(unmarked)
  string(REPLACE ";" "\n" text "${unmarked}")
  string(APPEND report "a function of an *_internal.h header without FLIPLAB_INTERNAL:\n${text}\n")
endif()
if(report)
  message(FATAL_ERROR "${report}")
endif()
if(STAMP)
  file(TOUCH ${STAMP})
endif()
