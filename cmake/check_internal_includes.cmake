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
# The private headers of CMakeLists.txt (fliplab_private_headers, passed as
# -DPRIVATE_HEADERS=FOLDER/NAME.h,...: lot/mesh.h) are held to the same
# rule, FOLDER standing for STEM (test_lot_walk.c may include mesh.h).
# Everything else a test needs goes through public verbs.  The scan also
# checks that every function of an *_internal.h or private header is marked
# FLIPLAB_INTERNAL (below).  Run as
#   cmake -DSOURCE_DIR=DIR [-DPRIVATE_HEADERS=LIST] [-DSTAMP=FILE] -P check_internal_includes.cmake
# Fails listing every offending include; on success touches STAMP.
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_internal_includes: set -DSOURCE_DIR")
endif()
set(offenders "")
# Private headers by name, with the stem (their folder) they belong to.
string(REPLACE "," ";" private "${PRIVATE_HEADERS}")
set(private_names "")
foreach(p ${private})
  get_filename_component(pname ${p} NAME)
  get_filename_component(pdir ${p} DIRECTORY)
  string(REPLACE "." "\\." pname_re ${pname})
  list(APPEND private_names ${pname_re})
  set(private_stem_${pname} ${pdir})
endforeach()
set(private_re "")
if(private_names)
  string(REPLACE ";" "|" private_re "${private_names}")
  set(private_re "|([^\">]*/)?(${private_re})[\">]")
endif()
foreach(dir cli plugins tests bench fuzz)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${dir}/*.c ${SOURCE_DIR}/${dir}/*.h
       ${SOURCE_DIR}/${dir}/*.cpp)
  foreach(f ${files})
    file(STRINGS ${f} lines
         REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]([^\">]*_internal\\.h[\">]${private_re})")
    get_filename_component(name ${f} NAME)
    foreach(line ${lines})
      if(line MATCHES "_internal\\.h[\">]")
        string(REGEX REPLACE ".*[\"</]([^\"</]*)_internal\\.h[\">].*" "\\1" stem "${line}")
      else()
        string(REGEX REPLACE ".*[\"</]([^\"</]*\\.h)[\">].*" "\\1" pname "${line}")
        set(stem ${private_stem_${pname}})
      endif()
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
  string(APPEND report "a private header (*_internal.h, or PRIVATE_HEADERS) included outside its own module "
         "(cmake/check_internal_includes.cmake says who may):\n${text}\n")
endif()

# And the other half of the rule: every function an *_internal.h header
# declares (a line at column 0 of the form TYPE name(, not static, inline,
# a typedef or a macro) carries FLIPLAB_INTERNAL (geom/fliplab_config.h),
# alone on the line before or in front, so a shared build exports none.
file(GLOB internal_headers ${SOURCE_DIR}/*/*_internal.h)
foreach(p ${private})
  if(EXISTS ${SOURCE_DIR}/${p})
    list(APPEND internal_headers ${SOURCE_DIR}/${p})
  endif()
endforeach()
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
