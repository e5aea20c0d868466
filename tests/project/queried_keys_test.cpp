// Keys are checked by what the loader reads ("queried" marks), not by a list kept beside the
// reads: a key nobody takes is named by its pointer with the keys that object was read for, a
// missing key points at a likely misspelling, the requirements are read once with the project,
// and an unknown near-field model names the file.
#include <gtest/gtest.h>

#include "project/json_reader.h"
#include "project/project_file.h"
#include "project_error.h"
#include "util/error.h"

namespace luxgrid::project {
using namespace calc;
namespace {

nlohmann::json office() {
  return nlohmann::json::parse(R"({
    "format": "luxgrid-project/1",
    "photometry": { "iso": { "builtin": "isotropic", "intensity_cd": 100 } },
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,3],[0,3]], "height": 2.5 } ],
    "luminaires": [ { "photometry": "iso", "position": [2, 1.5, 2.5] } ],
    "surfaces": [ { "name": "wp", "workplane": { "room": "r", "height": 0.8 }, "spacing": 0.5,
                    "requirements": { "Em": 500, "U0": 0.6 } } ]
  })");
}

TEST(QueriedKeys, AKeyNoReaderTakesIsNamedWithTheKeysItsObjectWasReadFor) {
  auto doc = office();
  doc["luminaires"][0]["rotaton"] = {0, 0, 90};
  // The luminaire reader took photometry and position and asked for the optional name, emitter,
  // rotation, array and emergency: those are the keys offered, in alphabetical order.
  EXPECT_EQ(error_of(doc),
            "p.json /luminaires/0/rotaton: unknown key \"rotaton\" (expected one of: array, "
            "emergency, emitter, name, photometry, position, rotation)");
}

TEST(QueriedKeys, TheKeysOfferedAreThoseTheBranchTakenAskedFor) {
  // A point emitter asks only whether "size" or "diameter" is there (to refuse them): with the
  // shape, those are the keys offered for a misspelt one.
  auto doc = office();
  doc["luminaires"][0]["emitter"] = {{"shape", "point"}, {"diameter_mm", 5}};
  EXPECT_EQ(error_of(doc),
            "p.json /luminaires/0/emitter/diameter_mm: unknown key \"diameter_mm\" "
            "(expected one of: diameter, shape, size)");
}

TEST(QueriedKeys, UnreadKeysDeepInsideAreFoundByTheirPointer) {
  auto doc = office();
  doc["rooms"][0]["obstacles"] = nlohmann::json::parse(
      R"([{ "name": "desk", "box": { "min": [1, 1, 0], "max": [2, 2, 0.7], "colour": "oak" } }])");
  EXPECT_EQ(error_of(doc),
            "p.json /rooms/0/obstacles/0/box/colour: unknown key \"colour\" "
            "(expected one of: max, min, rotation_z)");
}

TEST(QueriedKeys, AMissingKeyPointsAtItsLikelyMisspelling) {
  auto doc = office();
  doc["rooms"][0].erase("height");
  doc["rooms"][0]["heigth"] = 2.5;
  EXPECT_EQ(
      error_of(doc),
      "p.json /rooms/0: missing required key \"height\" (the object has \"heigth\": misspelt?)");
  // Nothing within two edits: no guess.
  doc["rooms"][0].erase("heigth");
  doc["rooms"][0]["z"] = 2.5;
  EXPECT_EQ(error_of(doc), "p.json /rooms/0: missing required key \"height\"");
}

TEST(QueriedKeys, RequirementsAreReadOnceWithTheProject) {
  const Project p = parse_project(office(), "p.json", ".");
  ASSERT_EQ(p.requirements.surfaces.count("wp"), 1u);
  EXPECT_EQ(p.requirements.surfaces.at("wp").limits.at("Em"), 500.0);
  EXPECT_EQ(p.requirements.surfaces.at("wp").limits.at("U0"), 0.6);
  auto doc = office();
  doc["surfaces"][0]["requirements"]["Eav"] = 500;
  EXPECT_EQ(error_of(doc).rfind("p.json /surfaces/0/requirements/Eav: unknown quantity \"Eav\"", 0),
            0u)
      << error_of(doc);
}

TEST(QueriedKeys, AnUnknownNearFieldModelNamesTheFile) {
  auto doc = office();
  doc["settings"] = {{"near_field_model", "lambert-9"}};
  EXPECT_EQ(
      error_of(doc).rfind(
          "p.json /settings/near_field_model: unknown model \"lambert-9\" (expected paper,", 0),
      0u)
      << error_of(doc);
}

TEST(QueriedKeys, FreeTextKeysAreAcceptedOnlyWhereSaid) {
  const auto doc =
      nlohmann::json::parse(R"({"notes": ["any", {"thing": 1}], "value": 2, "other": 3})");
  const JsonDocument document(doc, "e.json");
  const JsonValue root = document.root();
  root.accept_any("notes");
  EXPECT_EQ(root.at("value").as_number(), 2.0);
  try {
    root.report_unqueried();
    FAIL() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "e.json /other: unknown key \"other\" (expected one of: notes, value)");
    EXPECT_EQ(e.where().pointer, "/other");
    EXPECT_EQ(e.message(), "unknown key \"other\" (expected one of: notes, value)");
  }
}

// One rule for every message: the known parts of the place, in the order file, line, column,
// pointer, then ": " and the message.
TEST(SourceLocation, OneFormatForEveryKindOfPlace) {
  EXPECT_EQ(InputError(SourceLocation{"p.json", 12, 7}, "m").what(), std::string("p.json:12:7: m"));
  EXPECT_EQ(InputError(SourceLocation{"panel.ies", 14}, "m").what(),
            std::string("panel.ies:14: m"));
  EXPECT_EQ(InputError(SourceLocation{"p.json", 0, 0, "/rooms/0"}, "m").what(),
            std::string("p.json /rooms/0: m"));
  EXPECT_EQ(InputError(SourceLocation{"p.json", 3, 5, "/a"}, "m").what(),
            std::string("p.json:3:5 /a: m"));
  EXPECT_EQ(InputError(SourceLocation{"panel.ies"}, "m").what(), std::string("panel.ies: m"));
  EXPECT_EQ(InputError(SourceLocation{"", 0, 0, "/settings/x"}, "m").what(),
            std::string("/settings/x: m"));
  EXPECT_EQ(InputError("m").what(), std::string("m"));
  // A place found after reading (while calculating) gets the file it came from, once.
  const InputError late(SourceLocation{"", 0, 0, "/settings/x"}, "m");
  EXPECT_EQ(std::string(late.in_file("p.json").what()), "p.json /settings/x: m");
  EXPECT_EQ(std::string(late.in_file("p.json").in_file("q.json").what()), "p.json /settings/x: m");
}

}  // namespace
}  // namespace luxgrid::project
