# Writes OUT.gz: the man page of PROGRAM from its --help, by help2man, with the sections
# of INCLUDE. Run as cmake -DHELP2MAN=... -DPROGRAM=... -DNAME=... -DVERSION=... -DOUT=...
# -DINCLUDE=... -P make_man_page.cmake (from cmake/OflabInstall.cmake).
get_filename_component(dir "${OUT}" DIRECTORY)
file(MAKE_DIRECTORY "${dir}")
execute_process(
  COMMAND ${HELP2MAN} --no-info --no-discard-stderr --version-string=${VERSION}
          --include=${INCLUDE} --output=${OUT} ${PROGRAM}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed on ${PROGRAM}")
endif()
# help2man names the program by the file's name; gzip -n keeps the page reproducible.
execute_process(COMMAND gzip -9nf ${OUT} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gzip failed on ${OUT}")
endif()
