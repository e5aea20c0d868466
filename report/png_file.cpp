#include "report/png_file.h"

#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include <libdeflate.h>

#include "util/error.h"

namespace luxgrid::report {

namespace {

// The PNG file, as the PNG specification lays it out (docs/references.md, PNG): the signature, then
// chunks of a 4-byte big-endian length, a 4-byte type, the data and a CRC-32 of type and data.
// A plot needs three: IHDR (size, 8-bit RGB, no interlacing), one IDAT (every row after its
// filter byte, as one zlib stream) and IEND.
constexpr std::array<unsigned char, 8> kSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

// Plots are smooth colour ramps, flat margins and a little text. Row filters cost time and gain
// nothing on them (every row is written with filter 0, none). libdeflate's level 2 compresses
// them faster than zlib's level 3 did (through libpng), and faster and smaller than its own
// level 1, whose fastest matcher is slow on the plots' long runs of one colour (a megabyte of
// one colour: 3.3 ms at level 1, 1.4 ms at level 2): the office's 9 plots as 822 kB in 27 ms
// against 922 kB in 30 ms at level 1 (libdeflate 1.14, the plots' raw rows compressed in one
// process, 8 alternating rounds).
// The pixels are the same at any level (tests/report/png_plot_test.cpp decodes them).
constexpr int kDeflateLevel = 2;

void put_u32(std::string& out, std::uint32_t v) {
  const char bytes[4] = {static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                         static_cast<char>(v >> 8), static_cast<char>(v)};
  out.append(bytes, 4);
}

void put_chunk(std::string& out, const char (&type)[5], std::string_view data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t crc_from = out.size();
  out.append(type, 4);
  out.append(data);
  put_u32(out, libdeflate_crc32(0, out.data() + crc_from, out.size() - crc_from));
}

// One compressor and its output buffer per thread, kept between pictures: the plots are written
// in parallel, a compressor may serve one thread at a time, and a megabyte made anew for every
// picture would cost its page faults again. The buffer is left uninitialised, so only the pages
// a stream fills are touched.
struct Deflater {
  struct Free {
    void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
  };
  std::unique_ptr<libdeflate_compressor, Free> compressor{
      libdeflate_alloc_compressor(kDeflateLevel)};
  std::unique_ptr<unsigned char[]> stream;
  std::size_t capacity = 0;
};

// The PNG of `raster`: its scanlines are PNG's image data, each row after its filter byte 0.
std::string encode(const Raster& raster) {
  thread_local Deflater deflater;
  if (!deflater.compressor) throw CalculationError("cannot encode an image: out of memory");
  const std::span<const std::uint8_t> rows = raster.scanlines();
  libdeflate_compressor* c = deflater.compressor.get();
  const std::size_t bound = libdeflate_zlib_compress_bound(c, rows.size());
  if (bound > deflater.capacity)
    deflater.stream.reset(new unsigned char[bound]), deflater.capacity = bound;
  const std::size_t size =
      libdeflate_zlib_compress(c, rows.data(), rows.size(), deflater.stream.get(), bound);
  if (size == 0 || size > 0x7FFFFFFF) throw CalculationError("cannot encode an image: too large");

  std::string header;
  put_u32(header, static_cast<std::uint32_t>(raster.width()));
  put_u32(header, static_cast<std::uint32_t>(raster.height()));
  // 8 bits a channel, RGB, deflate, adaptive filtering (each row says its filter), no interlace
  header += std::string_view("\x08\x02\x00\x00\x00", 5);
  std::string png(kSignature.begin(), kSignature.end());
  png.reserve(png.size() + 3 * 12 + header.size() + size);
  put_chunk(png, "IHDR", header);
  put_chunk(png, "IDAT",
            std::string_view(reinterpret_cast<const char*>(deflater.stream.get()), size));
  put_chunk(png, "IEND", {});
  return png;
}

}  // namespace

std::string write_png(const Raster& raster, const std::filesystem::path& path) {
  const std::string png = encode(raster);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw CalculationError(path.string() + ": cannot write the image: cannot open the file");
  const bool written = std::fwrite(png.data(), 1, png.size(), f) == png.size();
  const bool closed = std::fclose(f) == 0;
  if (!written || !closed) {
    throw CalculationError(path.string() + ": cannot write the image: cannot " +
                           (written ? "close" : "write") + " the file");
  }
  return png;
}

std::string encode_png(const Raster& raster) { return encode(raster); }

}  // namespace luxgrid::report
