#pragma once
// NumPy's .npy format, version 1.0 [NEP1], for C-order little-endian float64 arrays: the magic
// "\x93NUMPY", version 1.0, a 2-byte little-endian header length, then a Python dict literal
// {'descr': '<f8', 'fortran_order': False, 'shape': (...), } padded with spaces and ended by
// '\n' so that the data starts at a multiple of 64 bytes, then the values row by row.
#include <cstddef>
#include <string>
#include <vector>

namespace luxgrid::report {

// The header (magic to newline) for an array of that shape. Throws CalculationError when the
// header would not fit version 1.0's 65535 bytes (not reachable with a few dimensions).
std::string npy_float64_header(const std::vector<std::size_t>& shape);

// Appends v as 8 little-endian bytes (IEEE 754 binary64), whatever the machine's byte order.
void append_float64_le(std::string& out, double v);

}  // namespace luxgrid::report
