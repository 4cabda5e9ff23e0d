# Assembles the one self-contained page: page.html with its markers replaced by the style
# (<!-- @style -->), the page's scripts (<!-- @scripts -->; SCRIPTS: their names in order,
# separated by commas, after BUNDLES: the bundled packages, vtk.js for the world view and
# webm-muxer for the videos, separated by commas) and the WebAssembly
# module's JavaScript with the wasm and the datasets inside (<!-- @module -->).
# Written to OUT through a temporary file renamed over it, so a failed run leaves no half page.
# Run as: cmake -DSOURCE_DIR=web -DMODULE=oflab_web.js -DOUT=oflab-web.html
#   -DSCRIPTS=app.js,flow_view.js,... -DBUNDLES=world_vtk.js,webm_writer.js -P assemble_page.cmake
file(READ "${SOURCE_DIR}/page.html" page)
file(READ "${SOURCE_DIR}/style.css" style)
file(READ "${MODULE}" module)
set(scripts "")
string(REPLACE "," ";" bundles "${BUNDLES}")
foreach(part IN LISTS bundles)
  file(READ "${part}" bundle)
  string(APPEND scripts "<script>\n${bundle}</script>\n")
endforeach()
string(REPLACE "," ";" scripts_in_order "${SCRIPTS}")
foreach(part IN LISTS scripts_in_order)
  file(READ "${SOURCE_DIR}/${part}" text)
  string(APPEND scripts "<script>\n// ${part}\n${text}</script>\n")
endforeach()
foreach(marker style scripts module)
  string(FIND "${page}" "<!-- @${marker} -->" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${SOURCE_DIR}/page.html: the marker <!-- @${marker} --> is missing")
  endif()
endforeach()
string(REPLACE "<!-- @style -->" "<style>\n${style}</style>" page "${page}")
string(REPLACE "<!-- @module -->" "<script>\n${module}</script>" page "${page}")
string(REPLACE "<!-- @scripts -->" "${scripts}" page "${page}")
file(WRITE "${OUT}.tmp" "${page}")
file(RENAME "${OUT}.tmp" "${OUT}")
