#pragma once
// Short pieces of text gathered in a fixed buffer and appended to a string a few hundred bytes
// at a time: a CSV row or a results.json element is a dozen pieces of a few characters, and a
// std::string append of each cost more than making the pieces.
#include <cstddef>
#include <cstring>
#include <string>
#include <string_view>

namespace luxgrid::report {

class PieceBuffer {
 public:
  explicit PieceBuffer(std::string& out) : out_(out) {}
  ~PieceBuffer() { flush(); }
  PieceBuffer(const PieceBuffer&) = delete;
  PieceBuffer& operator=(const PieceBuffer&) = delete;

  void put(std::string_view s) {
    if (s.size() > room()) {
      flush();
      if (s.size() > kCapacity) {
        out_.append(s);
        return;
      }
    }
    std::memcpy(end_, s.data(), s.size());
    end_ += s.size();
  }
  void put(char c) {
    if (room() == 0) flush();
    *end_++ = c;
  }
  void spaces(std::size_t n) {
    for (; n > kSpaces.size(); n -= kSpaces.size()) put(kSpaces);
    put(kSpaces.substr(0, n));
  }
  void flush() {
    out_.append(buf_, end_);
    end_ = buf_;
  }

 private:
  static constexpr std::size_t kCapacity = 1024;
  static constexpr std::string_view kSpaces = "                                ";
  std::size_t room() const { return static_cast<std::size_t>(buf_ + kCapacity - end_); }
  std::string& out_;
  char buf_[kCapacity];
  char* end_ = buf_;
};

}  // namespace luxgrid::report
