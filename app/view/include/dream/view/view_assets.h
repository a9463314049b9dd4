#pragma once

#include <string_view>

namespace dream::view {

/// One file of the page, embedded in the library at build time
/// (app/view/assets, embed_assets.cmake).
struct ViewAsset {
  std::string_view name;          ///< "index.html", "view.js", "view.css"
  std::string_view content_type;  ///< "text/html; charset=utf-8", ...
  std::string_view body;
};

/// The asset called `name` (no path: "view.js"); null when there is none.
const ViewAsset* FindViewAsset(std::string_view name);

}  // namespace dream::view
