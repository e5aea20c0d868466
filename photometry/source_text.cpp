#include "photometry/source_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "photometry/file_bytes.h"
#include "util/error.h"

namespace luxgrid::photometry {

SourceText::SourceText(std::string_view bytes, std::string name) : name_(std::move(name)) {
  check_size(bytes.size(), name_, kMaxPhotometryFileBytes, "photometric");
  if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);  // UTF-8 BOM (erco_sample17)
  text_.assign(bytes);
  std::string_view all(text_);
  std::size_t start = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i] == '\n' || all[i] == '\r') {
      lines_.push_back(all.substr(start, i - start));
      if (all[i] == '\r' && i + 1 < all.size() && all[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < all.size()) lines_.push_back(all.substr(start));
}

std::string_view SourceText::line(int number) const {
  if (number < 1 || number > line_count()) return {};
  return lines_[static_cast<std::size_t>(number - 1)];
}

std::string SourceText::where(int line) const {
  return line > 0 ? name_ + ":" + std::to_string(line) : name_;
}

void SourceText::fail(int line, const std::string& message) const {
  throw InputError(SourceLocation{name_, std::max(line, 0)}, message);
}

std::vector<Token> SourceText::tokens_from(int first_line) const {
  std::vector<Token> out;
  for (int n = std::max(first_line, 1); n <= line_count(); ++n) {
    std::string_view l = line(n);
    std::size_t i = 0;
    while (i < l.size()) {
      while (i < l.size() && (l[i] == ' ' || l[i] == '\t' || l[i] == ',' || l[i] == '\f' ||
                              l[i] == '\v' || l[i] == '\0'))
        ++i;
      std::size_t j = i;
      while (j < l.size() && !(l[j] == ' ' || l[j] == '\t' || l[j] == ',' || l[j] == '\f' ||
                               l[j] == '\v' || l[j] == '\0'))
        ++j;
      if (j > i) out.push_back({l.substr(i, j - i), n});
      i = j;
    }
  }
  return out;
}

bool try_parse_number(std::string_view s, double& out) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  if (s.empty()) return false;
  // from_chars would accept "inf"/"nan": only digits, sign, point and exponent are numbers here.
  for (char ch : s)
    if (!((ch >= '0' && ch <= '9') || ch == '-' || ch == '.' || ch == 'e' || ch == 'E' ||
          ch == '+'))
      return false;
  double v = 0.0;
  auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v)) return false;
  out = v;
  return true;
}

std::string quote_word(std::string_view word, std::size_t max_chars) {
  const bool printable = std::all_of(word.begin(), word.end(), [](char ch) {
    return static_cast<unsigned char>(ch) > 0x20 && static_cast<unsigned char>(ch) < 0x7F;
  });
  if (!printable)
    return "a " + std::to_string(word.size()) + "-byte word that is not printable ASCII";
  if (word.size() > max_chars) return "a " + std::to_string(word.size()) + "-character word";
  return "'" + std::string(word) + "'";
}

std::string describe_line(std::string_view line) {
  line = trim(line);
  if (line.empty()) return "an empty line";
  std::size_t words = 0;
  for (std::size_t i = 0; i < line.size(); ++i)
    if (line[i] != ' ' && line[i] != '\t' && (i == 0 || line[i - 1] == ' ' || line[i - 1] == '\t'))
      ++words;
  return words == 1 ? quote_word(line) : std::to_string(words) + " words";
}

double parse_number(const SourceText& src, const Token& t, const std::string& what) {
  double v = 0.0;
  if (!try_parse_number(t.text, v))
    src.fail(t.line, "expected a number for " + what + ", found " + quote_word(t.text));
  return v;
}

long parse_count(const SourceText& src, const Token& t, const std::string& what, long lo, long hi) {
  const double v = parse_number(src, t, what);
  if (v != std::floor(v))
    src.fail(t.line, "expected a whole number for " + what + ", found " + quote_word(t.text));
  if (v < static_cast<double>(lo) || v > static_cast<double>(hi))
    src.fail(t.line, "expected " + what + " between " + std::to_string(lo) + " and " +
                         std::to_string(hi) + ", found " + quote_word(t.text));
  return static_cast<long>(v);
}

void check_intensity(const SourceText& src, int line, const std::string& what, double value,
                     double scale) {
  const double cd = value * scale;
  if (!(cd <= kMaxIntensity_cd))
    src.fail(line, "expected " + what + " to be at most " + format_number(kMaxIntensity_cd) +
                       " cd after the multipliers, found " + format_number(value) + " x " +
                       format_number(scale) + " = " + format_number(cd) + " cd");
}

void check_lamp_flux(const SourceText& src, int line, const std::string& what, double flux_lm) {
  if (!(flux_lm > 0) || (flux_lm >= kMinLampFluxLm && flux_lm <= kMaxLampFluxLm)) return;
  src.fail(line, "expected " + what + " to be from " + format_number(kMinLampFluxLm) + " to " +
                     format_double("%.3g", kMaxLampFluxLm) + " lm (4 pi x the intensity limit of " +
                     format_number(kMaxIntensity_cd) + " cd), found " + format_number(flux_lm) +
                     " lm");
}

void check_opening_size(const SourceText& src, int line, const std::string& what, double metres) {
  if (!(std::abs(metres) > kMaxOpeningM)) return;
  src.fail(line, "expected " + what + " to be at most " + format_number(kMaxOpeningM) +
                     " m, found " + format_number(metres) + " m");
}

std::string_view trim(std::string_view s) {
  auto blank = [](char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\0' || c == '\f' || c == '\v';
  };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

std::string clean_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  std::size_t i = 0;
  auto latin1 = [&out](unsigned char c) {
    if (c < 0x80) {
      out.push_back(static_cast<char>(c));
    } else if (c < 0xA0) {
      out += "\xEF\xBF\xBD";  // C1 controls (cp1252 punctuation): replacement character
    } else {
      out.push_back(static_cast<char>(0xC0 | (c >> 6)));
      out.push_back(static_cast<char>(0x80 | (c & 0x3F)));
    }
  };
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      out.push_back(c < 0x20 && c != '\t' ? ' ' : static_cast<char>(c));
      ++i;
      continue;
    }
    // A well-formed UTF-8 sequence is kept as it is.
    int len = (c & 0xE0) == 0xC0 ? 2 : (c & 0xF0) == 0xE0 ? 3 : (c & 0xF8) == 0xF0 ? 4 : 0;
    bool ok = len > 0 && i + static_cast<std::size_t>(len) <= s.size() && c >= 0xC2 && c <= 0xF4;
    for (int k = 1; ok && k < len; ++k)
      ok = (static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]) & 0xC0) == 0x80;
    if (ok) {
      out.append(s.substr(i, static_cast<std::size_t>(len)));
      i += static_cast<std::size_t>(len);
    } else {
      latin1(c);
      ++i;
    }
  }
  return std::string(trim(out));
}

}  // namespace luxgrid::photometry
