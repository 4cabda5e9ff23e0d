# Install rules: the programs, their data and manual, and the core library as a CMake
# package (find_package(oflab) gives oflab::core; see manual/install.md). Included from
# the top-level CMakeLists.txt after the targets exist.
include(CMakePackageConfigHelpers)

# The core library: the static library, its headers under include/oflab/ (included as
# "flow/camera.h", like inside the tree) and the exported target oflab::core.
install(TARGETS oflab_core EXPORT oflabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${OFLAB_INSTALL_INCLUDEDIR})
install(DIRECTORY core/ DESTINATION ${OFLAB_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(EXPORT oflabTargets NAMESPACE oflab:: DESTINATION ${OFLAB_INSTALL_CMAKEDIR})
configure_package_config_file(cmake/oflabConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/oflabConfig.cmake INSTALL_DESTINATION ${OFLAB_INSTALL_CMAKEDIR})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/oflabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/oflabConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/oflabConfigVersion.cmake
        DESTINATION ${OFLAB_INSTALL_CMAKEDIR})

# The core-only and headless builds are test builds: they install the core library only.
if(OFLAB_CORE_ONLY OR OFLAB_HEADLESS)
  return()
endif()

# The programs and what they read at run time: datasets/ (found relative to bin/ by
# analysis/formats/datasets.cpp) and the manual.
install(TARGETS oflab oflab-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY datasets/ DESTINATION ${OFLAB_INSTALL_DATADIR}/datasets)
install(DIRECTORY manual/ DESTINATION ${OFLAB_INSTALL_DATADIR}/manual)
install(FILES README.md DESTINATION ${OFLAB_INSTALL_DATADIR})
# The browser page (manual/web.md), when tools/build-web.sh has built it: the desktop build
# never needs emscripten, so a missing page is skipped, not an error.
set(OFLAB_WEB_PAGE "${PROJECT_SOURCE_DIR}/build-web/oflab-web.html"
    CACHE FILEPATH "The browser page installed under share/oflab/web/ when it exists")
install(FILES ${OFLAB_WEB_PAGE} DESTINATION ${OFLAB_INSTALL_DATADIR}/web OPTIONAL)

# The menu entry, its icon and the licence.
install(FILES packaging/oflab.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES packaging/oflab.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES packaging/copyright DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/oflab)

# Man pages from the programs' --help (help2man), at build time.
find_program(OFLAB_HELP2MAN help2man)
if(OFLAB_HELP2MAN)
  set(man_pages)
  foreach(program oflab oflab-cli)
    set(page ${CMAKE_CURRENT_BINARY_DIR}/man/${program}.1)
    add_custom_command(OUTPUT ${page}.gz
      COMMAND ${CMAKE_COMMAND} -DHELP2MAN=${OFLAB_HELP2MAN} -DPROGRAM=$<TARGET_FILE:${program}>
              -DNAME=${program} -DVERSION=${PROJECT_VERSION} -DOUT=${page}
              -DINCLUDE=${PROJECT_SOURCE_DIR}/packaging/${program}.h2m
              -P ${PROJECT_SOURCE_DIR}/cmake/make_man_page.cmake
      DEPENDS ${program} ${PROJECT_SOURCE_DIR}/packaging/${program}.h2m
              ${PROJECT_SOURCE_DIR}/cmake/make_man_page.cmake
      COMMENT "Man page of ${program} from its --help")
    list(APPEND man_pages ${page}.gz)
  endforeach()
  add_custom_target(oflab_man_pages ALL DEPENDS ${man_pages})
  install(FILES ${man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man pages (tools/install-deps.sh installs it)")
endif()

include(cmake/OflabPackage.cmake)
