#include "dream/render/render_format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace dream::render {

std::optional<RenderFormat> RenderFormatOfPath(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return RenderFormat::kPng;
  if (extension == ".svg") return RenderFormat::kSvg;
  if (extension == ".mp4") return RenderFormat::kMp4;
  if (extension == ".gif") return RenderFormat::kGif;
  return std::nullopt;
}

const char* RenderFormatExtensions() { return ".png, .svg, .mp4, .gif"; }

}  // namespace dream::render
