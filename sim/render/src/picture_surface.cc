#include "picture_surface.h"

#include <cairo-svg.h>
#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "dream/files/atomic_file.h"

namespace dream::render {
namespace {

void AppendPng(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}

void FlushNothing(png_structp) {}

// An image surface (ARGB32, premultiplied) as PNG bytes, the pixels exactly
// as cairo's own writer stores them, written about three times faster:
// pictures of runs are flat colours and lines, which deflate level 1 without
// row filters packs as small as cairo's defaults (level 6, every filter tried
// per row), and an opaque picture is stored without its alpha channel.
std::string PngBytes(cairo_surface_t* surface) {
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  bool opaque = true;
  for (int y = 0; y < height && opaque; ++y) {
    const auto* pixels = reinterpret_cast<const uint32_t*>(data + static_cast<size_t>(y) * static_cast<size_t>(stride));
    for (int x = 0; x < width; ++x) {
      if ((pixels[x] >> 24) != 0xff) {
        opaque = false;
        break;
      }
    }
  }
  const int channels = opaque ? 3 : 4;
  std::string bytes;
  std::vector<png_byte> row(static_cast<size_t>(width) * static_cast<size_t>(channels));
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png != nullptr ? png_create_info_struct(png) : nullptr;
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    throw std::runtime_error("out of memory for a PNG");
  }
  // libpng reports errors by longjmp: nothing above needs destroying on the way.
  if (setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng could not encode the picture");
  }
  png_set_write_fn(png, &bytes, &AppendPng, &FlushNothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               opaque ? PNG_COLOR_TYPE_RGB : PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y) {
    const auto* pixels = reinterpret_cast<const uint32_t*>(data + static_cast<size_t>(y) * static_cast<size_t>(stride));
    png_byte* out = row.data();
    for (int x = 0; x < width; ++x) {
      const uint32_t pixel = pixels[x];
      const uint32_t alpha = pixel >> 24;
      uint32_t red = (pixel >> 16) & 0xff;
      uint32_t green = (pixel >> 8) & 0xff;
      uint32_t blue = pixel & 0xff;
      if (alpha != 0xff && alpha != 0) {  // un-premultiply, rounding as cairo does
        red = (red * 255 + alpha / 2) / alpha;
        green = (green * 255 + alpha / 2) / alpha;
        blue = (blue * 255 + alpha / 2) / alpha;
      }
      *out++ = static_cast<png_byte>(red);
      *out++ = static_cast<png_byte>(green);
      *out++ = static_cast<png_byte>(blue);
      if (!opaque) *out++ = static_cast<png_byte>(alpha);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return bytes;
}

}  // namespace

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
    bytes = PngBytes(surface_);
  } else if (status == CAIRO_STATUS_SUCCESS) {
    cairo_surface_finish(surface_);  // flushes the rest of the SVG into svg_bytes_
    status = cairo_surface_status(surface_);
    bytes.swap(svg_bytes_);
  }
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error("cannot draw " + path + ": " + cairo_status_to_string(status));
  }
  files::WriteFileAtomically(path, bytes);
}

}  // namespace dream::render
