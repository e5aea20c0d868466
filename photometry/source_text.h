#pragma once
// The text of a photometric file as the readers see it: split into lines (LF, CRLF or CR), a
// UTF-8 byte-order mark dropped, every error naming "file:line". Both readers count lines here so
// that messages look alike (docs/reliability.md: `panel.ies:14: expected 37 vertical angles, found
// 36`).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "photometry/limits.h"
#include "util/format.h"  // format_number, for the readers' messages

namespace luxgrid::photometry {

struct Token {
  std::string_view text;
  int line;  // 1-based
};

class SourceText {
 public:
  SourceText(std::string_view bytes, std::string name);

  const std::string& name() const { return name_; }
  int line_count() const { return static_cast<int>(lines_.size()); }
  // 1-based; returns "" past the end.
  std::string_view line(int number) const;

  // Throws InputError "name:line: message" (or "name: message" for line <= 0).
  [[noreturn]] void fail(int line, const std::string& message) const;
  std::string where(int line) const;

  // Every token from `first_line` on, split at blanks, tabs and commas (LM-63 allows commas as
  // separators; lithonia_esg uses them).
  std::vector<Token> tokens_from(int first_line) const;

 private:
  std::string name_;
  std::string text_;
  std::vector<std::string_view> lines_;
};

// Strict number parsing for a token: the whole token must be a finite number ("1", "-.1", "750.",
// "1e3"; a leading '+' is accepted). `what` names the field in the message.
double parse_number(const SourceText& src, const Token& t, const std::string& what);
// As parse_number, and the value must be a whole number within [lo, hi].
long parse_count(const SourceText& src, const Token& t, const std::string& what, long lo, long hi);
// Fails at `line` unless value x scale (a stored intensity times every multiplier) is at most
// kMaxIntensity_cd (limits.h); NaN and infinity fail too. `what` names the value.
void check_intensity(const SourceText& src, int line, const std::string& what, double value,
                     double scale);
// Fails at `line` when a stated lamp flux is above 0 but outside [kMinLampFluxLm,
// kMaxLampFluxLm] (limits.h); 0 and below are the callers' to judge (absolute photometry).
void check_lamp_flux(const SourceText& src, int line, const std::string& what, double flux_lm);
// Fails at `line` when |metres| (a luminous opening dimension, converted) exceeds
// kMaxOpeningM (limits.h).
void check_opening_size(const SourceText& src, int line, const std::string& what, double metres);
// Parses without throwing; false if not a finite number.
bool try_parse_number(std::string_view s, double& out);

// What a message may show of a word of the file (limits.h, kMaxQuotedWordChars): the word
// quoted ("'abc'") when it is printable ASCII and at most `max_chars` long, otherwise a
// description that quotes nothing ("a 47-character word", "a 3-byte word that is not printable
// ASCII"). Messages never quote more of a file than this.
std::string quote_word(std::string_view word, std::size_t max_chars = kMaxQuotedWordChars);
// The same for a whole line, which may hold several words: "an empty line", one word as
// quote_word, or "4 words" (quoting none: a line of words is rarely a number gone wrong).
std::string describe_line(std::string_view line);

// Text from the file made printable and valid UTF-8 (bytes that are not UTF-8 are read as
// Latin-1, which is what cp1252 degree signs and no-break spaces in the corpus are), trimmed.
std::string clean_text(std::string_view s);
std::string_view trim(std::string_view s);

}  // namespace luxgrid::photometry
