#include "picture_surface.h"

#include <cairo-svg.h>

#include <stdexcept>

#include "dream/node/atomic_file.h"

namespace dream::sim {

PictureSurface::PictureSurface(RenderFormat format, int width_px, int height_px) : format_(format) {
  if (format == RenderFormat::kPng) {
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width_px, height_px);
  } else if (format == RenderFormat::kSvg) {
    surface_ = cairo_svg_surface_create_for_stream(&PictureSurface::Append, &svg_bytes_, width_px, height_px);
  } else {
    throw std::invalid_argument("a picture is .png or .svg");
  }
  cr_ = cairo_create(surface_);
}

PictureSurface::~PictureSurface() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

cairo_status_t PictureSurface::Append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

void PictureSurface::Commit(const std::string& path) {
  std::string bytes;
  cairo_status_t status = cairo_status(cr_);
  if (status == CAIRO_STATUS_SUCCESS && format_ == RenderFormat::kPng) {
    cairo_surface_flush(surface_);
    status = cairo_surface_write_to_png_stream(surface_, &PictureSurface::Append, &bytes);
  } else if (status == CAIRO_STATUS_SUCCESS) {
    cairo_surface_finish(surface_);  // flushes the rest of the SVG into svg_bytes_
    status = cairo_surface_status(surface_);
    bytes.swap(svg_bytes_);
  }
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot draw " + path + ": " + cairo_status_to_string(status));
  }
  WriteFileAtomically(path, bytes);
}

}  // namespace dream::sim
