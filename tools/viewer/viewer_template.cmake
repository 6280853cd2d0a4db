# The viewer's template, embedded into the dlfl tool: viewer.html with viewer.js put in place of its
# <script src="viewer.js"> element, as one string in a generated header (viewer_template.h). Read at configure
# time; editing either file re-runs the configuration. The page loads nothing else: no network, no npm.
set(DLFL_VIEWER_DIR ${CMAKE_CURRENT_LIST_DIR})
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${DLFL_VIEWER_DIR}/viewer.html
                                                               ${DLFL_VIEWER_DIR}/viewer.js)
file(READ ${DLFL_VIEWER_DIR}/viewer.html dlfl_viewer_html)
file(READ ${DLFL_VIEWER_DIR}/viewer.js dlfl_viewer_js)
set(dlfl_viewer_script_tag "<script src=\"viewer.js\"></script>")
string(FIND "${dlfl_viewer_html}" "${dlfl_viewer_script_tag}" dlfl_viewer_at)
if(dlfl_viewer_at EQUAL -1)
  message(FATAL_ERROR "tools/viewer/viewer.html lacks ${dlfl_viewer_script_tag}")
endif()
string(REPLACE "${dlfl_viewer_script_tag}" "<script>\n${dlfl_viewer_js}</script>" dlfl_viewer_page
               "${dlfl_viewer_html}")
string(FIND "${dlfl_viewer_page}" ")dlfl_viewer\"" dlfl_viewer_at)
if(NOT dlfl_viewer_at EQUAL -1)
  message(FATAL_ERROR "tools/viewer/ contains the raw string's delimiter )dlfl_viewer\"")
endif()
set(DLFL_VIEWER_GENERATED ${CMAKE_CURRENT_BINARY_DIR}/generated)
# Written through a copy so that an unchanged template leaves the header's time alone (no rebuild).
set(dlfl_viewer_header "#pragma once\n// Generated from tools/viewer/ by viewer_template.cmake: do not edit.\n")
string(APPEND dlfl_viewer_header "#include <string_view>\nnamespace dlfl::tool {\n")
string(APPEND dlfl_viewer_header "inline constexpr std::string_view viewer_template = R\"dlfl_viewer(")
string(APPEND dlfl_viewer_header "${dlfl_viewer_page})dlfl_viewer\";\n}  // namespace dlfl::tool\n")
file(WRITE ${DLFL_VIEWER_GENERATED}/viewer_template.h.new "${dlfl_viewer_header}")
configure_file(${DLFL_VIEWER_GENERATED}/viewer_template.h.new ${DLFL_VIEWER_GENERATED}/viewer_template.h COPYONLY)
target_include_directories(dlfl_tool PRIVATE ${DLFL_VIEWER_GENERATED})
