# Builds the manual: runs doxygen, then, when the pages load MathJax from a local copy
# (MATHJAX_DIR given), copies that MathJax 2 into html/mathjax and checks that no page still
# loads MathJax from the network. The target `doc` and the test doc.doxygen both run it
# (doc/CMakeLists.txt):
#   cmake -DDOXYGEN=doxygen -DDOXYFILE=<build>/doc/Doxyfile -DHTML_DIR=<output>/html
#         [-DMATHJAX_DIR=/usr/share/javascript/mathjax] -P doc/build_doc.cmake
# Doxygen's output goes to this script's standard output and error as it is: the test's
# FAIL_REGULAR_EXPRESSION sees its warnings.
cmake_minimum_required(VERSION 3.14)

foreach(var DOXYGEN DOXYFILE HTML_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "build_doc.cmake: -D${var}=... is required")
  endif()
endforeach()

execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE doxygen_result)
if(NOT doxygen_result EQUAL 0)
  message(FATAL_ERROR "doxygen failed (${doxygen_result})")
endif()

if(NOT MATHJAX_DIR)
  return()   # the pages load MathJax from a URL (HOT_DOC_MATHJAX_RELPATH)
endif()
if(NOT EXISTS "${MATHJAX_DIR}/MathJax.js")
  message(FATAL_ERROR "no MathJax.js in ${MATHJAX_DIR}")
endif()

# Everything a page can load: MathJax.js, jax/ (input, element and every output, since the
# reader may switch renderers in MathJax's menu), extensions/, fonts/, localization/. Left
# out: unpacked/ (the same files unminified), test/, and config/ (combined configurations,
# loaded only through MathJax.js?config=..., which doxygen's pages do not use): about 23 MB of
# Debian's 54. file(COPY) skips the files already copied and unchanged.
string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" mathjax_dir_regex "${MATHJAX_DIR}")
file(COPY "${MATHJAX_DIR}/" DESTINATION "${HTML_DIR}/mathjax"
     REGEX "^${mathjax_dir_regex}/+(unpacked|test|config)$" EXCLUDE)
if(NOT EXISTS "${HTML_DIR}/mathjax/MathJax.js")
  message(FATAL_ERROR "copying ${MATHJAX_DIR} into ${HTML_DIR}/mathjax failed")
endif()

# self-contained: no page may load MathJax from the network
string(REGEX REPLACE "([][+.*()^$?|\\\\])" "\\\\\\1" html_dir_regex "${HTML_DIR}")
file(GLOB_RECURSE pages "${HTML_DIR}/*.html")
list(FILTER pages EXCLUDE REGEX "^${html_dir_regex}/mathjax/")
set(pages_with_mathjax 0)
foreach(page IN LISTS pages)
  file(STRINGS "${page}" remote REGEX "https?://[^\"' ]*[Mm]ath[Jj]ax")
  if(remote)
    message(FATAL_ERROR "${page} loads MathJax from the network: ${remote}")
  endif()
  file(STRINGS "${page}" local REGEX "src=\"(\\.\\./)*mathjax/MathJax\\.js\"")
  if(local)
    math(EXPR pages_with_mathjax "${pages_with_mathjax} + 1")
  endif()
endforeach()
if(pages_with_mathjax EQUAL 0)
  message(FATAL_ERROR "no page of ${HTML_DIR} loads mathjax/MathJax.js")
endif()
message(STATUS "MathJax: ${MATHJAX_DIR} copied into ${HTML_DIR}/mathjax (${pages_with_mathjax} pages use it)")
