#pragma once

#include <cairo.h>

#include <memory>
#include <string>

#include "dream/render/render_format.h"

namespace dream::render {

/// A cairo surface that becomes a PNG (pixels) or an SVG (vectors) file.
/// Nothing touches the file until Commit(), which writes it atomically: a
/// file that exists is complete.
class PictureSurface {
 public:
  /// @throws std::invalid_argument for a video format.
  PictureSurface(RenderFormat format, int width_px, int height_px);
  ~PictureSurface();
  PictureSurface(const PictureSurface&) = delete;
  PictureSurface& operator=(const PictureSurface&) = delete;

  cairo_t* cr() const { return cr_; }
  /// Finishes the drawing and writes it to `path`.
  /// @throws std::runtime_error naming the path when it cannot be written.
  void Commit(const std::string& path);

 private:
  static cairo_status_t Append(void* closure, const unsigned char* data, unsigned int length);

  RenderFormat format_;
  std::string svg_bytes_;  // the SVG surface streams here as it is drawn
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace dream::render
