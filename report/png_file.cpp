#include "report/png_file.h"

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <png.h>
#include <zlib.h>

#include "util/error.h"

namespace luxgrid::report {

namespace {

constexpr int kZlibLevel = 3;

// libpng reports errors by longjmp: this function holds no object with a destructor between
// setjmp and the calls that may jump, so nothing is skipped. Returns "" or the reason.
std::string encode(std::FILE* file, int width, int height, png_bytep* rows) {
  static thread_local std::string message;
  message.clear();
  png_structp png = png_create_write_struct(
      PNG_LIBPNG_VER_STRING, nullptr,
      [](png_structp p, png_const_charp m) {
        message = m;
        png_longjmp(p, 1);
      },
      [](png_structp, png_const_charp) {});
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return "out of memory";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return message.empty() ? "libpng error" : message;
  }
  png_init_io(png, file);
  // Plots are smooth colour ramps, flat margins and a little text. Row filters cost time and
  // gain nothing on them (libpng's adaptive filtering took twice as long at about the same size),
  // and zlib's level 3 takes half the time of its default level 6: measured on the office's 24
  // plots, 2.6 MiB against 1.9 MiB (+34 %; level 1 is +50 % for a few per cent less time), the
  // report phase 0.75 s against 0.9-1.15 s on one thread of a loaded machine. The pixels are the
  // same at any level (tests/report/png_plot_test.cpp decodes them).
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, kZlibLevel);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return "";
}

}  // namespace

void write_png(const Raster& raster, const std::filesystem::path& path) {
  std::vector<png_bytep> rows(static_cast<std::size_t>(raster.height()));
  auto* base = const_cast<png_bytep>(raster.pixels().data());  // libpng only reads the rows
  for (int y = 0; y < raster.height(); ++y)
    rows[y] = base + static_cast<std::size_t>(y) * raster.width() * 3;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw CalculationError(path.string() + ": cannot write the image: cannot open the file");
  std::string error = encode(f, raster.width(), raster.height(), rows.data());
  if (std::fclose(f) != 0 && error.empty()) error = "cannot close the file";
  if (!error.empty()) throw CalculationError(path.string() + ": cannot write the image: " + error);
}

std::string encode_png(const Raster& raster) {
  std::vector<png_bytep> rows(static_cast<std::size_t>(raster.height()));
  auto* base = const_cast<png_bytep>(raster.pixels().data());
  for (int y = 0; y < raster.height(); ++y)
    rows[y] = base + static_cast<std::size_t>(y) * raster.width() * 3;
  // The same encoder as write_png, into a POSIX memory stream.
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* f = open_memstream(&buffer, &size);
  if (!f) throw CalculationError("cannot encode an image: out of memory");
  const std::string error = encode(f, raster.width(), raster.height(), rows.data());
  std::fclose(f);
  std::string bytes(buffer ? buffer : "", buffer ? size : 0);
  std::free(buffer);
  if (!error.empty()) throw CalculationError("cannot encode an image: " + error);
  return bytes;
}

}  // namespace luxgrid::report
