#include "report/npy.h"

#include <bit>
#include <cstdint>

#include "util/error.h"

namespace luxgrid::report {

std::string npy_float64_header(const std::vector<std::size_t>& shape) {
  std::string dims;
  for (std::size_t d : shape) dims += std::to_string(d) + ", ";
  if (shape.size() > 1)
    dims.resize(dims.size() - 2);  // (3,) for one dimension, (3, 6) for two
  else if (!shape.empty())
    dims.pop_back();
  std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + dims + "), }";
  constexpr std::size_t kPreamble = 10;  // magic (6), version (2), header length (2)
  constexpr std::size_t kAlign = 64;
  const std::size_t total = (kPreamble + dict.size() + 1 + kAlign - 1) / kAlign * kAlign;
  const std::size_t header_len = total - kPreamble;
  if (header_len > 0xFFFF)
    throw CalculationError("array shape too long for a .npy version 1.0 header");
  dict.append(header_len - dict.size() - 1, ' ');
  dict += '\n';
  std::string out = "\x93NUMPY";
  out += '\x01';
  out += '\x00';
  out += static_cast<char>(header_len & 0xFF);
  out += static_cast<char>(header_len >> 8);
  return out + dict;
}

void append_float64_le(std::string& out, double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  for (int k = 0; k < 8; ++k) out += static_cast<char>((bits >> (8 * k)) & 0xFF);
}

}  // namespace luxgrid::report
