#include "project/safe_json.h"

#include <fstream>
#include <iterator>
#include <map>
#include <utility>
#include <vector>

#include "project/json_reader.h"
#include "util/error.h"
#include "util/file_kind.h"

namespace luxgrid::project {

namespace {

// A character iterator that publishes how far the parser has read. nlohmann's SAX events carry
// no position; the lexer reads through this iterator, so at each event `*read` is just past the
// token that caused it (the '{' of an object, the closing quote of a key).
class CountingIterator {
 public:
  using iterator_category = std::forward_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator() = default;
  CountingIterator(const char* p, const char** read) : p_(p), read_(read) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    *read_ = ++p_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }

 private:
  const char* p_ = nullptr;
  const char** read_ = nullptr;
};

// The line and column of the last character read when `consumed` characters have been read (the
// same convention as nlohmann's parse_error::byte).
std::pair<int, int> line_column(std::string_view text, std::size_t consumed) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i + 1 < consumed && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

// nlohmann's DOM builder with three checks in front of it. It tracks where it is (one frame per
// open object or array: the key or index of the child being read, and an object's keys so far
// with where each was read), so the checks can name the JSON pointer. Given JsonPositions, it
// records where each value begins (project/json_positions.h).
class CheckedDomBuilder {
 public:
  using json = nlohmann::json;

  CheckedDomBuilder(json& root, std::string_view text, const std::string& label,
                    const char* const* read, JsonPositions* positions)
      : dom_(root), root_(root), text_(text), label_(label), read_(read), positions_(positions) {}

  bool null() {
    return scalar(consumed() - 4, [&] { return dom_.null(); });
  }
  bool boolean(bool v) {
    return scalar(consumed() - (v ? 4 : 5), [&] { return dom_.boolean(v); });
  }
  bool number_integer(json::number_integer_t v) {
    return scalar(start_of_number(), [&] { return dom_.number_integer(v); });
  }
  bool number_unsigned(json::number_unsigned_t v) {
    return scalar(start_of_number(), [&] { return dom_.number_unsigned(v); });
  }
  bool number_float(json::number_float_t v, const std::string& s) {
    return scalar(start_of_number(), [&] { return dom_.number_float(v, s); });
  }
  bool string(std::string& v) {
    return scalar(start_of_string(), [&] { return dom_.string(v); });
  }
  bool binary(json::binary_t& v) {
    return scalar(consumed(), [&] { return dom_.binary(v); });
  }

  bool start_object(std::size_t n) {
    open();
    const bool ok = dom_.start_object(n);
    push(false);
    return ok;
  }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    f.child = json_pointer_escape(k);
    const auto [it, fresh] = f.keys.emplace(k, consumed());
    if (!fresh) {
      fail(consumed(), pointer(),
           "duplicate key \"" + k + "\" (first given on line " +
               std::to_string(line_column(text_, it->second).first) + ")");
    }
    const bool ok = dom_.key(k);
    if (positions_) f.member = &(*f.container)[k];  // the member's node: it stays where it is
    return ok;
  }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    open();
    const bool ok = dom_.start_array(n);
    push(true);
    return ok;
  }
  bool end_array() {
    // The array is complete: its elements no longer move.
    Frame& f = frames_.back();
    for (std::size_t i = 0; i < f.elements.size(); ++i)
      positions_->add(&(*f.container)[i], f.elements[i]);
    frames_.pop_back();
    return dom_.end_array();
  }

  bool parse_error(std::size_t byte, const std::string& /*last_token*/,
                   const nlohmann::detail::exception& ex) {
    std::string what = ex.what();
    // nlohmann's 406: a number that is not a finite double (1e400). Name it and its place.
    if (ex.id == 406) {
      const auto quote = what.find('\'');
      const std::string number =
          quote == std::string::npos ? "" : what.substr(quote + 1, what.size() - quote - 2);
      fail(byte, pointer_of_next_value(),
           "the number " + number + " is out of range (a number must fit a double, |x| < 1.8e308)");
    }
    // nlohmann ends with "; last read: '<bytes>'": those bytes are not shown (they may be any
    // file's), only what was wrong.
    const auto syntax = what.find("syntax error");
    std::string message = syntax != std::string::npos ? what.substr(syntax) : what;
    const auto last_read = message.find("; last read:");
    if (last_read != std::string::npos) message.erase(last_read);
    fail(byte, "", "malformed JSON: " + message);
  }

 private:
  struct Frame {
    bool is_array = false;
    std::size_t next_index = 0;
    std::string child;                        // escaped key or index of the value being read
    std::map<std::string, std::size_t> keys;  // object keys so far -> characters read at each
    // With positions only: the object or array itself, the member being read (objects) and
    // where each element began (arrays: their addresses are known once the array is complete).
    json* container = nullptr;
    json* member = nullptr;
    std::vector<TextPosition> elements;
  };

  std::size_t consumed() const { return static_cast<std::size_t>(*read_ - text_.data()); }
  [[noreturn]] void fail(std::size_t at, const std::string& pointer,
                         const std::string& message) const {
    const auto [line, column] = line_column(text_, at);
    throw InputError(SourceLocation{label_, line, column, pointer}, message);
  }

  // A value starts: in an array, it is the next element.
  bool next_value() {
    if (!frames_.empty() && frames_.back().is_array) {
      frames_.back().child = std::to_string(frames_.back().next_index++);
    }
    return true;
  }

  // A scalar value that began at byte `start`, added to the DOM by `add`.
  template <class Add>
  bool scalar(std::size_t start, Add&& add) {
    next_value();
    if (!add()) return false;
    place(start);
    return true;
  }

  void open() {
    next_value();
    if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      fail(consumed(), "",
           "objects and arrays nested deeper than the limit of " + std::to_string(kMaxJsonDepth) +
               " levels");
    }
  }
  // After the DOM has the new object or array: its frame, and its place (its '{' or '[').
  void push(bool is_array) {
    json* self = nullptr;
    if (positions_) {
      self = frames_.empty()           ? &root_
             : frames_.back().is_array ? &frames_.back().container->back()
                                       : frames_.back().member;
      place(consumed() - 1);
    }
    frames_.push_back(Frame{is_array, 0, {}, {}, self, nullptr, {}});
  }

  // Records that the value just added to the DOM began at byte `start`.
  void place(std::size_t start) {
    if (!positions_) return;
    const TextPosition at = position_of(start);
    if (frames_.empty()) {
      positions_->set_root(at);
    } else if (frames_.back().is_array) {
      frames_.back().elements.push_back(at);
    } else {
      positions_->add(frames_.back().member, at);
    }
  }
  // The line and column of byte `start`: values come in text order, so the lines are counted
  // once over the whole text.
  TextPosition position_of(std::size_t start) {
    if (start < line_scanned_) line_scanned_ = 0, line_ = 1, line_start_ = 0;
    for (; line_scanned_ < start && line_scanned_ < text_.size(); ++line_scanned_) {
      if (text_[line_scanned_] == '\n') {
        ++line_;
        line_start_ = line_scanned_ + 1;
      }
    }
    return {line_, static_cast<int>(start - line_start_ + 1)};
  }
  // Where the string just read began: its closing quote was the last byte read, its opening
  // quote is the nearest quote before it that no backslash escapes (an even run of backslashes).
  std::size_t start_of_string() const {
    std::size_t i = consumed() - 1;
    while (i > 0) {
      --i;
      if (text_[i] != '"') continue;
      std::size_t slashes = 0;
      while (i > slashes && text_[i - 1 - slashes] == '\\') ++slashes;
      if (slashes % 2 == 0) return i;
    }
    return 0;
  }
  // Where the number just read began: the lexer has read one byte past it (unless it ended the
  // text), and what precedes a number is never part of one.
  std::size_t start_of_number() const {
    const auto in_number = [](char c) {
      return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
    };
    std::size_t i = consumed();
    if (i > 0 && !in_number(text_[i - 1])) --i;
    while (i > 0 && in_number(text_[i - 1])) --i;
    return i;
  }

  std::string pointer() const {
    std::string p;
    for (const auto& f : frames_) p += "/" + f.child;
    return p.empty() ? "/" : p;
  }
  // Where a value being read now goes (before its event was delivered).
  std::string pointer_of_next_value() {
    if (!frames_.empty() && frames_.back().is_array) {
      frames_.back().child = std::to_string(frames_.back().next_index);
    }
    return pointer();
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  json& root_;
  std::string_view text_;
  const std::string& label_;
  const char* const* read_;
  JsonPositions* positions_;
  std::vector<Frame> frames_;
  std::size_t line_scanned_ = 0;  // position_of's count: bytes scanned, the line and its start
  int line_ = 1;
  std::size_t line_start_ = 0;
};

// JSON is UTF-8 text (RFC 8259 section 8.1): say so for a UTF-16 or UTF-32 file (what Windows
// editors save as "Unicode") and for binary data, instead of a syntax error at 1:1.
void check_is_utf8_text(std::string_view text, const std::string& label) {
  const auto starts = [&](std::string_view bom) { return text.substr(0, bom.size()) == bom; };
  if (starts("\xFF\xFE") || starts("\xFE\xFF") || starts(std::string_view("\0\0\xFE\xFF", 4)))
    throw InputError(SourceLocation{label}, "the file is UTF-16 or UTF-32 text; save it as UTF-8");
  // NUL and the other C0 controls but tab, LF and CR never occur in JSON text (RFC 8259
  // section 7: inside strings they must be escaped).
  const std::string_view head = text.substr(0, 4096);
  for (char ch : head) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r')
      throw InputError(SourceLocation{label}, "expected a JSON text file, found binary data");
  }
}

}  // namespace

nlohmann::json parse_json_text(std::string_view text, const std::string& label,
                               JsonPositions* positions) {
  check_is_utf8_text(text, label);
  nlohmann::json doc;
  const char* read = text.data();
  CheckedDomBuilder builder(doc, text, label, &read, positions);
  nlohmann::json::sax_parse(CountingIterator(text.data(), &read),
                            CountingIterator(text.data() + text.size(), &read), &builder);
  if (positions) positions->finish();
  return doc;
}

std::string read_bounded_file(const std::filesystem::path& file, std::uintmax_t max_bytes,
                              const std::string& kind) {
  // By stat, before any open (util/file_kind.h): a FIFO would block the open. A missing file
  // keeps its message below.
  if (const std::string what = not_a_regular_file(file); !what.empty() && what != "file not found")
    throw InputError(SourceLocation{file.string()}, what);
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(file, ec);
  if (ec) throw InputError(SourceLocation{file.string()}, "cannot open the " + kind);
  if (bytes > max_bytes) {
    throw InputError(SourceLocation{file.string()},
                     "the file is " + std::to_string(bytes) + " bytes, more than the limit of " +
                         std::to_string(max_bytes) + " bytes (" + std::to_string(max_bytes >> 20) +
                         " MiB) for a " + kind);
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(SourceLocation{file.string()}, "cannot open the " + kind);
  std::string text(static_cast<std::size_t>(bytes), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  return text;
}

nlohmann::json read_json_file(const std::filesystem::path& file, std::uintmax_t max_bytes,
                              const std::string& kind) {
  return parse_json_text(read_bounded_file(file, max_bytes, kind), file.string());
}

}  // namespace luxgrid::project
