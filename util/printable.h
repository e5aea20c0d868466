#pragma once
// Text from a user's file made safe to print: a JSON key may hold any character as an escape
// (`"rot\u0000ation"`), and printed raw, a NUL ends the C string a message is printed from and
// other control characters move the terminal's cursor, so a message was cut off or named the
// wrong key. Every message prints through located_message (util/error.h), which passes it here.
#include <cstdio>
#include <string>
#include <string_view>

namespace luxgrid {

// `text` with each C0 control character (U+0000..U+001F) and DEL (U+007F) written as JSON
// writes it, `\u0000`; every other byte unchanged (UTF-8 stays UTF-8).
inline std::string printable_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7F) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04X", c);
      out += code;
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace luxgrid
