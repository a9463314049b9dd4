#include "dream/view/view_assets.h"

#include <string_view>
#include <utility>
#include <vector>

namespace dream::view {

// Generated from app/view/assets by embed_assets.cmake.
const std::vector<std::pair<std::string_view, std::string_view>>& EmbeddedAssets();

namespace {

std::string_view ContentType(std::string_view name) {
  const auto ends_with = [&](std::string_view suffix) {
    return name.size() >= suffix.size() && name.substr(name.size() - suffix.size()) == suffix;
  };
  if (ends_with(".html")) return "text/html; charset=utf-8";
  if (ends_with(".js")) return "text/javascript; charset=utf-8";
  if (ends_with(".css")) return "text/css; charset=utf-8";
  return "application/octet-stream";
}

std::vector<ViewAsset> MakeAssets() {
  std::vector<ViewAsset> assets;
  for (const auto& [name, body] : EmbeddedAssets()) assets.push_back({name, ContentType(name), body});
  return assets;
}

}  // namespace

const ViewAsset* FindViewAsset(std::string_view name) {
  static const std::vector<ViewAsset> kAssets = MakeAssets();
  for (const ViewAsset& asset : kAssets) {
    if (asset.name == name) return &asset;
  }
  return nullptr;
}

}  // namespace dream::view
