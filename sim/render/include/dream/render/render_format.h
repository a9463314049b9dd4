#pragma once

#include <optional>
#include <string>

namespace dream::render {

/// The files `dream render` writes, picked by the output's extension.
enum class RenderFormat { kPng, kSvg, kMp4, kGif };

/// The format of `path` by its extension (case-insensitive), or nothing.
std::optional<RenderFormat> RenderFormatOfPath(const std::string& path);
/// ".png, .svg, .mp4, .gif": for messages.
const char* RenderFormatExtensions();
/// True for PNG and SVG (pictures), false for MP4 and GIF (videos).
inline bool IsPictureFormat(RenderFormat format) {
  return format == RenderFormat::kPng || format == RenderFormat::kSvg;
}

}  // namespace dream::render
