#include "report/raster.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "util/error.h"

namespace luxgrid::report {

Raster::Raster(int width, int height, Rgb background) : width_(width), height_(height) {
  if (width <= 0 || height <= 0) throw CalculationError("cannot make an empty picture");
  const std::uint8_t r = to_byte(background.r), g = to_byte(background.g),
                     b = to_byte(background.b);
  // A grey background (white, for the plots) is one byte repeated: filled as such at once, then
  // each row's filter-type byte.
  const std::size_t stride = static_cast<std::size_t>(width) * 3 + 1;
  data_ = LargeBuffer<std::uint8_t>::filled(stride * static_cast<std::size_t>(height), r);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* p = row(y);
    p[-1] = 0;
    if (g != r || b != r)
      for (int x = 0; x < width; ++x) p[3 * x + 1] = g, p[3 * x + 2] = b;
  }
}

std::vector<std::uint8_t> Raster::pixels() const {
  std::vector<std::uint8_t> rgb;
  rgb.reserve(static_cast<std::size_t>(width_) * height_ * 3);
  for (int y = 0; y < height_; ++y) rgb.insert(rgb.end(), row(y), row(y) + width_ * 3);
  return rgb;
}

Rgb Raster::at(int x, int y) const {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return {};
  const std::size_t k = offset(x, y);
  return {data_[k] / 255.f, data_[k + 1] / 255.f, data_[k + 2] / 255.f};
}

void Raster::blend(int x, int y, Rgb c, float alpha) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_ || !(alpha > 0.f)) return;
  alpha = std::min(alpha, 1.f);
  const Rgb old = at(x, y);
  set(x, y,
      {old.r + (c.r - old.r) * alpha, old.g + (c.g - old.g) * alpha,
       old.b + (c.b - old.b) * alpha});
}

void Raster::fill(int x0, int x1, int y0, int y1, Rgb c) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, width_), y1 = std::min(y1, height_);
  if (x0 >= x1 || y0 >= y1) return;
  const std::uint8_t r = to_byte(c.r), g = to_byte(c.g), b = to_byte(c.b);
  for (int y = y0; y < y1; ++y) {
    std::uint8_t* p = row(y) + static_cast<std::size_t>(x0) * 3;
    for (int x = x0; x < x1; ++x, p += 3) p[0] = r, p[1] = g, p[2] = b;
  }
}

void Raster::line(int x0, int y0, int x1, int y1, Rgb c) {
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  int err = dx + dy;
  for (;;) {
    set(x0, y0, c);
    if (x0 == x1 && y0 == y1) return;
    const int e2 = 2 * err;
    if (e2 >= dy) err += dy, x0 += sx;
    if (e2 <= dx) err += dx, y0 += sy;
  }
}

void Raster::box(int x0, int y0, int x1, int y1, Rgb c, bool filled) {
  if (x1 < x0) std::swap(x0, x1);
  if (y1 < y0) std::swap(y0, y1);
  if (filled) return fill(x0, x1 + 1, y0, y1 + 1, c);
  fill(x0, x1 + 1, y0, y0 + 1, c);
  fill(x0, x1 + 1, y1, y1 + 1, c);
  fill(x0, x0 + 1, y0, y1 + 1, c);
  fill(x1, x1 + 1, y0, y1 + 1, c);
}

}  // namespace luxgrid::report
