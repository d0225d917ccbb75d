#pragma once
/// @file
/// The page of `tailor view`, embedded in the executable at build time (cmake/viewer.cmake
/// runs web/build.mjs: web/src bundled with three.js from web/node_modules into one
/// classic script), so that `tailor view` needs neither network nor node at run time.

#include <string>

namespace tailor::cli {

/// web/src/index.html.
std::string viewer_index_html();

/// The bundled, minified page script (three.js included, its licence kept); empty when
/// the build had no web/node_modules.
std::string viewer_script();

}  // namespace tailor::cli
