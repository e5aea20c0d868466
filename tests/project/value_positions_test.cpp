// Every complaint about a value of a project names its line and column as well as its JSON
// pointer (project/json_positions.h): the safe parse records where each value begins, and the
// loader's messages carry it. Columns count bytes from 1.
#include <gtest/gtest.h>

#include <string>

#include "project/json_positions.h"
#include "project/project_file.h"
#include "project/safe_json.h"
#include "util/error.h"

namespace luxgrid::project {
namespace {

std::string error_of_text(const std::string& text) {
  try {
    (void)parse_project_text(text, "p.json", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// The first line of a project and its empty photometry, then `rooms` (from line 4 on).
std::string project_with_rooms(const std::string& rooms) {
  return "{\n"
         "  \"format\": \"luxgrid-project/1\",\n"
         "  \"photometry\": {},\n" +
         rooms + "}\n";
}

TEST(ValuePositions, WrongTypeNamesItsLineAndColumn) {
  const std::string text = project_with_rooms(
      "  \"rooms\": [\n"                                                // line 4
      "    {\"name\": \"A\", \"outline\": [[0, 0], [4, 0], [4, 3]],\n"  // line 5
      "     \"height\": \"3\"}\n"                                       // line 6: "3" at column 16
      "  ]\n");
  EXPECT_EQ(error_of_text(text), "p.json:6:16 /rooms/0/height: expected a number, got a string");
}

TEST(ValuePositions, NestedArrayElementNamesItsLineAndColumn) {
  // /rooms/0/outline/2/1: an element of an array inside an array inside an object inside an
  // array; the strings before it on its line hold escaped quotes and backslashes.
  const std::string text = project_with_rooms(
      "  \"rooms\": [\n"
      "    {\"height\": 3,\n"
      "     \"name\": \"A \\\"b\\\" \\\\\", \"outline\": [[0, 0], [4, 0], [4, \"3\"]]}\n"
      "  ]\n");
  const std::string line6 =
      "     \"name\": \"A \\\"b\\\" \\\\\", \"outline\": [[0, 0], [4, 0], [4, ";
  EXPECT_EQ(error_of_text(text), "p.json:6:" + std::to_string(line6.size() + 1) +
                                     " /rooms/0/outline/2/1: expected a number, got a string");
}

TEST(ValuePositions, NumberOutOfRangeOfItsKeyNamesWhereTheNumberBegins) {
  const std::string text = project_with_rooms(
      "  \"rooms\": [{\"name\": \"A\", \"outline\": [[0, 0], [4, 0], [4, 3]],\n"
      "\t\"height\": -2.5e0}]\n");  // the tab is one column; "-" is at column 12
  EXPECT_EQ(error_of_text(text),
            "p.json:5:12 /rooms/0/height: expected a positive number, got -2.5");
}

TEST(ValuePositions, TheRootIsWhereTheDocumentBegins) {
  EXPECT_EQ(error_of_text("\n\n  [true, null]"), "p.json:3:3 /: expected an object, got an array");
}

TEST(ValuePositions, UnknownKeyNamesWhereItsValueBegins) {
  const std::string text = project_with_rooms(
      "  \"settings\": {\"quality\": \"draft\",\n"
      "    \"colour\": null}\n");  // line 5, null at column 15
  const std::string expected = "p.json:5:15 /settings/colour: unknown key \"colour\" (";
  EXPECT_EQ(error_of_text(text).substr(0, expected.size()), expected);
}

TEST(ValuePositions, EveryValueOfAParsedDocumentHasItsPosition) {
  // Literals, numbers at the end of the text, strings with escapes, arrays in arrays: each
  // value's recorded position is where its first character is.
  const std::string text =
      "{\"a\": [1, -2e3, \"x\\\"\", [true, false, null], {\"b\": 0.5}],\n\"c\": 7}";
  JsonPositions positions;
  const nlohmann::json doc = parse_json_text(text, "p.json", &positions);
  const auto column_of = [&](const std::string& token, size_t from = 0) {
    return static_cast<int>(text.find(token, from) + 1);
  };
  const auto& a = doc["a"];
  EXPECT_EQ(positions.of(a).column, column_of("["));
  EXPECT_EQ(positions.of(a[0]).column, column_of("1"));
  EXPECT_EQ(positions.of(a[1]).column, column_of("-2e3"));
  EXPECT_EQ(positions.of(a[2]).column, column_of("\"x"));
  EXPECT_EQ(positions.of(a[3]).column, column_of("[true"));
  EXPECT_EQ(positions.of(a[3][0]).column, column_of("true"));
  EXPECT_EQ(positions.of(a[3][1]).column, column_of("false"));
  EXPECT_EQ(positions.of(a[3][2]).column, column_of("null"));
  EXPECT_EQ(positions.of(a[4]).column, column_of("{\"b\""));
  EXPECT_EQ(positions.of(a[4]["b"]).column, column_of("0.5"));
  for (const auto* v : {&a, &a[0], &a[3][2], &a[4]["b"]}) EXPECT_EQ(positions.of(*v).line, 1);
  EXPECT_EQ(positions.of(doc["c"]).line, 2);
  EXPECT_EQ(positions.of(doc["c"]).column, 6);
  EXPECT_EQ(positions.root().line, 1);
  EXPECT_EQ(positions.root().column, 1);
  // A copy is another document: its values are not known (line 0, the pointer alone).
  const nlohmann::json copy = doc;
  EXPECT_EQ(positions.of(copy["c"]).line, 0);
}

TEST(ValuePositions, WarningsNameTheirPlaceByTheSameRule) {
  // A clockwise room outline (line 6, its "[" at column 16) is legal: reversed, with a warning
  // printed as errors are, file:line:column /pointer: message.
  const std::string text = project_with_rooms(
      "  \"luminaires\": [],\n"
      "  \"rooms\": [{\"name\": \"A\", \"height\": 3,\n"
      "    \"outline\": [[0, 3], [4, 3], [4, 0], [0, 0]]}],\n"
      "  \"surfaces\": [{\"name\": \"p\", \"points\": [{\"at\": [1, 1, 0], \"normal\": [0, 0, "
      "1]}]}]\n");
  const auto warnings = parse_project_text(text, "p.json", ".").scene.warnings;
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].where.line, 6);
  EXPECT_EQ(warnings[0].where.column, 16);
  EXPECT_EQ(warnings[0].text(),
            "p.json:6:16 /rooms/0/outline: room \"A\": the outline is clockwise; reversed to "
            "counter-clockwise");
  EXPECT_EQ(warnings[0].text(), InputError(warnings[0].where, warnings[0].message).what());
}

}  // namespace
}  // namespace luxgrid::project
