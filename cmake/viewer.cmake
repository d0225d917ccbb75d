# `tailor view` (issue 16): the page script is web/src bundled with three.js by esbuild
# (web/build.mjs; both pinned in web/package-lock.json, installed by scripts/install-deps.sh
# with `npm ci`) and embedded into the tailor executable, so that running `tailor view`
# needs neither node nor network. Without node or web/node_modules the executable is built
# without the page, and `tailor view` says so. Also registers the headless-Chromium test.

set(TAILOR_WEB_DIR ${PROJECT_SOURCE_DIR}/web)
set(TAILOR_VIEW_ASSETS ${CMAKE_CURRENT_BINARY_DIR}/generated/view_assets.cpp)
find_program(TAILOR_NODE node)
if(TAILOR_NODE AND EXISTS ${TAILOR_WEB_DIR}/node_modules/three/package.json
   AND EXISTS ${TAILOR_WEB_DIR}/node_modules/esbuild/package.json)
  file(GLOB TAILOR_WEB_SOURCES CONFIGURE_DEPENDS ${TAILOR_WEB_DIR}/src/*)
  add_custom_command(
    OUTPUT ${TAILOR_VIEW_ASSETS} ${CMAKE_CURRENT_BINARY_DIR}/generated/viewer.js
    COMMAND ${TAILOR_NODE} ${TAILOR_WEB_DIR}/build.mjs
            --out ${CMAKE_CURRENT_BINARY_DIR}/generated/viewer.js --cpp ${TAILOR_VIEW_ASSETS}
    DEPENDS ${TAILOR_WEB_SOURCES} ${TAILOR_WEB_DIR}/build.mjs ${TAILOR_WEB_DIR}/package-lock.json
    WORKING_DIRECTORY ${TAILOR_WEB_DIR}
    COMMENT "Bundling the tailor view page (three.js) into the executable"
    VERBATIM)
else()
  message(STATUS "tailor view: no node or web/node_modules (run scripts/install-deps.sh): "
                 "building without the viewer page")
  file(CONFIGURE OUTPUT ${TAILOR_VIEW_ASSETS} CONTENT [[
// Written by cmake/viewer.cmake: this build has no viewer page (no web/node_modules).
#include "view/view_assets.hpp"

namespace tailor::cli {
std::string viewer_index_html() { return {}; }
std::string viewer_script() { return {}; }
}  // namespace tailor::cli
]])
endif()
target_sources(tailor_cli PRIVATE ${TAILOR_VIEW_ASSETS})

# The browser test: a short simulation and a detected step, written by `tailor view` and
# opened in Debian's headless Chromium through puppeteer-core (tests/view/browser_test.mjs).
# The simulation writes its own contact files, so the red candidate triangles are required.
# It skips (exit 77) with a message when Chromium or the node packages are missing.
if(TAILOR_BUILD_TESTS)
  if(TAILOR_NODE)
    add_test(NAME view.browser
             COMMAND ${TAILOR_NODE} ${PROJECT_SOURCE_DIR}/tests/view/browser_test.mjs
                     --tailor $<TARGET_FILE:tailor_cli>
                     --work ${CMAKE_CURRENT_BINARY_DIR}/view-browser-test
                     --no-fixture --expect-red)
  else()
    add_test(NAME view.browser
             COMMAND sh -c "echo 'view.browser skipped: node is not installed (scripts/install-deps.sh)'; exit 77")
  endif()
  set_tests_properties(view.browser PROPERTIES SKIP_RETURN_CODE 77 TIMEOUT 240)
endif()
