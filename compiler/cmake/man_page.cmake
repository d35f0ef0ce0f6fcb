# Writes OUT, hexc's man page (hexc.1.gz), from `HEXC --help` by help2man (HELP2MAN), with INCLUDE's sections added:
#   cmake -DHELP2MAN=... -DHEXC=... -DVERSION=... -DINCLUDE=... -DOUT=... -P man_page.cmake
# The same tree makes the same bytes: help2man dates the page by the build's month, so the date is left empty, and
# gzip -n stores no name or time.
execute_process(COMMAND ${HEXC} --help OUTPUT_VARIABLE help COMMAND_ERROR_IS_FATAL ANY)
# The NAME line, "hexc - <what it does>": the help's first line says it.
string(REGEX MATCH "^hexc - ([^\n]+)" name "${help}")
if(NOT name)
  message(FATAL_ERROR "`hexc --help` does not start with \"hexc - <what it does>\"")
endif()
set(ENV{SOURCE_DATE_EPOCH} 0)
execute_process(COMMAND ${HELP2MAN} --no-info --section 1 --name "${CMAKE_MATCH_1}" --version-string "hexc ${VERSION}"
                        --include ${INCLUDE} ${HEXC}
                OUTPUT_VARIABLE page COMMAND_ERROR_IS_FATAL ANY)
string(REGEX REPLACE "\n\\.TH ([^\n]*) \"January 1970\" " "\n.TH \\1 \"\" " page "${page}")
if(page MATCHES "1970")
  message(FATAL_ERROR "help2man's page holds a date this script does not take out")
endif()
get_filename_component(dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
file(WRITE ${OUT}.tmp "${page}")
execute_process(COMMAND gzip -n -9 -c ${OUT}.tmp OUTPUT_FILE ${OUT} COMMAND_ERROR_IS_FATAL ANY)
file(REMOVE ${OUT}.tmp)
