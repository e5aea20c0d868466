#pragma once
// The text of a number, formatted once for each value that repeats. A grid's coordinates take a
// few hundred values (x by column, y by row, z and the normal once), its unlit or unreflected
// points write 0 and a room without reflected light writes E_direct = E: most of a CSV row's or
// of results.json's numbers were formatted a moment before. Formatting a double costs about
// 100 ns; looking it up here a few. The text is the formatter's own (the key is the value's bit
// pattern, so -0 and 0, or two NaNs, are told apart): a memo changes no byte of the output.
#include <array>
#include <bit>
#include <cstdint>
#include <string_view>
#include <vector>

namespace luxgrid::report {

// `Format(double, char* first)` writes at most kMaxChars characters and returns the end.
template <class Format>
class NumberTextMemo {
 public:
  static constexpr std::size_t kMaxChars = 30;

  explicit NumberTextMemo(Format format = Format{})
      : format_(format), table_(std::size_t{1} << kLogSlots) {}

  std::string_view text(double v) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
    // Fibonacci hashing: neighbouring values (a row's x) spread over the table.
    Entry& e = table_[(bits * 0x9E3779B97F4A7C15ull) >> (64 - kLogSlots)];
    if (!e.used || e.bits != bits) {
      e.bits = bits;
      e.used = true;
      e.length = static_cast<std::uint8_t>(format_(v, e.chars.data()) - e.chars.data());
    }
    return {e.chars.data(), e.length};
  }

 private:
  // 4096 slots (about 160 kB, on the heap): a 1000-point row's x values and the rest fit
  // without evicting one another often.
  static constexpr int kLogSlots = 12;
  struct Entry {
    std::uint64_t bits = 0;
    bool used = false;
    std::uint8_t length = 0;
    std::array<char, kMaxChars> chars;
  };
  Format format_;
  std::vector<Entry> table_;
};

}  // namespace luxgrid::report
