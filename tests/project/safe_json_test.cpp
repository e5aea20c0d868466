// The safe JSON parse: hostile project text fails with one exact message naming the place, and
// never crashes (deep nesting), never answers silently (duplicate keys), never escapes as an
// unexpected exception (1e400).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <string>

#include "project/safe_json.h"
#include "temp_folder.h"
#include "util/error.h"

namespace luxgrid::project {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_json_text(text, "p.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// Column of the character at `offset` on a one-line text.
std::string column_of(size_t offset) { return std::to_string(offset + 1); }

TEST(SafeJson, ValidTextParses) {
  const auto doc = parse_json_text(R"({"a": [1, 2.5, "x", null, true, {"b": {}}]})", "p.json");
  EXPECT_EQ(doc["a"][1], 2.5);
  EXPECT_EQ(doc["a"][5]["b"], nlohmann::json::object());
}

TEST(SafeJson, HundredThousandNestedObjectsAreRefusedAtTheLimit) {
  // The measured crash: an unknown key holding 100 000 nested objects overflowed the stack when
  // the document was copied. The parse must stop at level 65, before any of it is kept.
  constexpr int kLevels = 100000;
  const std::string prefix = "{\"x\": ";
  std::string text = prefix;
  for (int i = 0; i < kLevels; ++i) text += "{\"a\":";
  text += "1";
  text += std::string(kLevels, '}') + "}";
  // The root is level 1; the 64th "{" of the chain opens level 65.
  const size_t offset = prefix.size() + 63 * 5;
  EXPECT_EQ(error_of(text), "p.json:1:" + column_of(offset) +
                                ": objects and arrays nested deeper than the limit of 64 levels");
}

TEST(SafeJson, HundredThousandNestedArraysAreRefusedAtTheLimit) {
  const std::string text = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(error_of(text),
            "p.json:1:65: objects and arrays nested deeper than the limit of 64 levels");
}

TEST(SafeJson, SixtyFourLevelsAreAccepted) {
  const std::string text = std::string(64, '[') + std::string(64, ']');
  EXPECT_NO_THROW(parse_json_text(text, "p.json"));
}

TEST(SafeJson, DuplicateTopLevelKeyNamesPointerAndBothLines) {
  // Last-wins made `"luminaires": []` silently give 0 lx.
  const std::string text =
      "{\"format\": \"luxgrid-project/1\",\n \"luminaires\": [1],\n \"luminaires\": []}";
  EXPECT_EQ(error_of(text),
            "p.json:3:13 /luminaires: duplicate key \"luminaires\" (first given on line 2)");
}

TEST(SafeJson, DuplicateNestedKeyNamesItsPointer) {
  const std::string text = R"({"settings": {"quality": "draft", "quality": "high"}})";
  const size_t closing_quote = text.rfind("\"quality\"") + 8;
  EXPECT_EQ(error_of(text),
            "p.json:1:" + column_of(closing_quote) +
                " /settings/quality: duplicate key \"quality\" (first given on line 1)");
}

TEST(SafeJson, DuplicateKeyInsideAnArrayNamesTheIndex) {
  const std::string text = R"({"surfaces": [{"name": "a"}, {"name": "b", "name": "c"}]})";
  const size_t closing_quote = text.rfind("\"name\"") + 5;
  EXPECT_EQ(error_of(text),
            "p.json:1:" + column_of(closing_quote) +
                " /surfaces/1/name: duplicate key \"name\" (first given on line 1)");
}

TEST(SafeJson, SameKeyInSiblingObjectsIsFine) {
  EXPECT_NO_THROW(parse_json_text(R"([{"a": 1}, {"a": 2}, {"b": {"a": 3}}])", "p.json"));
}

TEST(SafeJson, NumberBeyondDoubleIsBadInputWithPointer) {
  const std::string text = R"({"settings": {"bounces": 1e400}})";
  const size_t end = text.find("1e400") + 4;  // nlohmann points at the number's last character
  EXPECT_EQ(error_of(text),
            "p.json:1:" + column_of(end) +
                " /settings/bounces: the number 1e400 is out of range (a number must "
                "fit a double, |x| < 1.8e308)");
}

TEST(SafeJson, NegativeNumberBeyondDoubleInAnArray) {
  const std::string text = R"({"luminaires": [{"position": [1, -1e400, 2]}]})";
  const size_t end = text.find("-1e400") + 5;
  EXPECT_EQ(error_of(text), "p.json:1:" + column_of(end) +
                                " /luminaires/0/position/1: the number -1e400 is out of range (a "
                                "number must fit a double, |x| < 1.8e308)");
}

TEST(SafeJson, SyntaxErrorNamesLineAndColumn) {
  EXPECT_EQ(error_of("{\n  \"a\": 1\n  \"b\": 2\n}"),
            "p.json:3:5: malformed JSON: syntax error while parsing object - unexpected string "
            "literal; expected '}'");
}

TEST(SafeJson, FileLargerThanTheLimitIsRefusedBeforeReading) {
  const testing_support::TempFolder dir;
  const auto file = dir.write("huge.json", "{}");
  // Sparse: the size is what counts, no 16 MB is written or read.
  std::filesystem::resize_file(file, kMaxProjectFileBytes + 1);
  try {
    read_json_file(file);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() +
                                         ": the file is 16777217 bytes, more than the "
                                         "limit of 16777216 bytes (16 MiB) for a project file");
  }
}

TEST(SafeJson, MissingFileIsInputError) {
  const testing_support::TempFolder dir;
  const auto file = dir.path() / "none.json";
  try {
    read_json_file(file);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ": cannot open the project file");
  }
}

// A FIFO as the project file: named for what it is, found without opening it (an open would
// wait for a writer, and this test would never end); a folder likewise.
TEST(SafeJson, FifoOrFolderIsNamedNotOpened) {
  const testing_support::TempFolder dir;
  const auto fifo = dir.path() / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    read_json_file(fifo);
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              fifo.string() + ": is a FIFO (named pipe), not a regular file");
  }
  try {
    read_json_file(dir.path());
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), dir.path().string() + ": is a folder, not a file");
  }
}

}  // namespace
}  // namespace luxgrid::project
