#pragma once
// An 8-bit sRGB picture in memory and the few drawing primitives the plots need: filled
// rectangles, lines, boxes and alpha blending (text is drawn by report/raster_text.h, the file
// is written by report/png_file.h). Everything is clipped to the picture, so callers may draw
// partly outside it. The picture is kept as PNG's image data before compression (each row after
// a filter-type byte), so the PNG writer compresses it as it is, without a megabyte's copy.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "util/large_buffer.h"

namespace luxgrid::report {

// A colour in sRGB, each channel in [0, 1] (stored rounded to 8 bits).
struct Rgb {
  float r = 0.f, g = 0.f, b = 0.f;
};

// A colour as the raster stores it: each channel rounded to a byte (Raster::to_bytes).
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb8&) const = default;
};

class Raster {
 public:
  Raster(int width, int height, Rgb background);

  int width() const { return width_; }
  int height() const { return height_; }
  // Row-major, the top row first, 3 bytes (R, G, B) per pixel (a copy).
  std::vector<std::uint8_t> pixels() const;
  // Each row, the top row first, as PNG filters it: a filter-type byte 0 (none), then the row's
  // pixels as pixels() has them.
  std::span<const std::uint8_t> scanlines() const { return data_.span(); }
  // Row y's first pixel byte (0 <= y < height()), for callers that fill whole rows of bytes.
  std::uint8_t* row(int y) { return data_.data() + offset(0, y); }
  const std::uint8_t* row(int y) const { return data_.data() + offset(0, y); }
  Rgb at(int x, int y) const;

  void set(int x, int y, Rgb c) {  // inline: the plots set each of their pixels
    if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
    const std::size_t k = offset(x, y);
    data_[k] = to_byte(c.r), data_[k + 1] = to_byte(c.g), data_[k + 2] = to_byte(c.b);
  }
  // round(v 255) to the nearest byte, halves away from zero, as std::lround does: v 255 + 0.5 is
  // exact in double for every float in [0, 255], so truncating it rounds the same way without
  // lround's call. NaN gives 0, as lround's result cast to a byte did.
  static std::uint8_t to_byte(float v) {
    const float scaled = std::clamp(v, 0.f, 1.f) * 255.f;
    if (!(scaled >= 0.f)) return 0;
    return static_cast<std::uint8_t>(static_cast<int>(static_cast<double>(scaled) + 0.5));
  }
  static Rgb8 to_bytes(Rgb c) { return {to_byte(c.r), to_byte(c.g), to_byte(c.b)}; }
  // c over the pixel with coverage alpha in [0, 1] (anti-aliased text).
  void blend(int x, int y, Rgb c, float alpha);
  // The half-open rectangle [x0, x1) x [y0, y1).
  void fill(int x0, int x1, int y0, int y1, Rgb c);
  // Bresenham's line, both end points drawn.
  void line(int x0, int y0, int x1, int y1, Rgb c);
  // The rectangle with corners (x0, y0) and (x1, y1), both included: filled or its outline.
  void box(int x0, int y0, int x1, int y1, Rgb c, bool filled);

 private:
  std::size_t offset(int x, int y) const {
    return static_cast<std::size_t>(y) * (static_cast<std::size_t>(width_) * 3 + 1) + 1 +
           static_cast<std::size_t>(x) * 3;
  }
  int width_, height_;
  // scanlines(): a plot's megabyte, in huge pages where the system gives them
  // (util/large_buffer.h).
  LargeBuffer<std::uint8_t> data_;
};

}  // namespace luxgrid::report
