#pragma once

#include <cairo.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

namespace dream::render::testing {

// Colours the pictures use, 0..1 (robots: matplotlib's tab10).
inline constexpr std::array<double, 3> kRobot0Blue = {0.12, 0.47, 0.71};
inline constexpr std::array<double, 3> kRobot1Orange = {1.00, 0.50, 0.05};
inline constexpr std::array<double, 3> kWhite = {1, 1, 1};
inline constexpr std::array<double, 3> kObstacleGrey = {0.25, 0.25, 0.25};

/// A PNG decoded with cairo, to check what was drawn where.
class PicturePixels {
 public:
  explicit PicturePixels(const std::string& png_path)
      : surface_(cairo_image_surface_create_from_png(png_path.c_str())) {
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
      cairo_surface_destroy(surface_);
      throw std::runtime_error("cannot decode " + png_path);
    }
  }
  ~PicturePixels() { cairo_surface_destroy(surface_); }
  PicturePixels(const PicturePixels&) = delete;
  PicturePixels& operator=(const PicturePixels&) = delete;

  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }

  /// {r, g, b} 0..255 of the pixel at (x, y), rounded to the nearest pixel.
  std::array<int, 3> Rgb(double x, double y) const {
    const int column = static_cast<int>(x);
    const int row = static_cast<int>(y);
    if (column < 0 || row < 0 || column >= width() || row >= height()) throw std::out_of_range("pixel outside");
    const unsigned char* data = cairo_image_surface_get_data(surface_);
    uint32_t word = 0;
    std::memcpy(&word, data + row * cairo_image_surface_get_stride(surface_) + column * 4, 4);
    return {static_cast<int>(word >> 16 & 0xff), static_cast<int>(word >> 8 & 0xff), static_cast<int>(word & 0xff)};
  }

  /// True when the pixel is within `tolerance` of `rgb` (0..1 components) in every channel.
  bool Near(double x, double y, const std::array<double, 3>& rgb, int tolerance = 12) const {
    const std::array<int, 3> got = Rgb(x, y);
    for (int c = 0; c < 3; ++c) {
      if (std::abs(got[static_cast<size_t>(c)] - static_cast<int>(rgb[static_cast<size_t>(c)] * 255 + 0.5)) >
          tolerance) {
        return false;
      }
    }
    return true;
  }

  /// How many pixels of the rectangle [x0, x1) x [y0, y1) are within `tolerance` of `rgb`.
  int CountNear(double x0, double y0, double x1, double y1, const std::array<double, 3>& rgb,
                int tolerance = 12) const {
    int count = 0;
    for (int y = static_cast<int>(y0); y < static_cast<int>(y1); ++y) {
      for (int x = static_cast<int>(x0); x < static_cast<int>(x1); ++x) count += Near(x, y, rgb, tolerance) ? 1 : 0;
    }
    return count;
  }

  /// How many pixels of the rectangle [x0, x1) x [y0, y1) are not white.
  int CountInk(double x0, double y0, double x1, double y1) const {
    int count = 0;
    for (int y = static_cast<int>(y0); y < static_cast<int>(y1); ++y) {
      for (int x = static_cast<int>(x0); x < static_cast<int>(x1); ++x) count += Near(x, y, {1, 1, 1}, 8) ? 0 : 1;
    }
    return count;
  }

 private:
  cairo_surface_t* surface_;
};

}  // namespace dream::render::testing
