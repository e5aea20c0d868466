// results.json follows docs/project-format.md, key by key.
#include <sstream>

#include <gtest/gtest.h>

#include "report/colour_scale.h"
#include "report/results_json.h"
#include "util/sha256.h"

namespace luxgrid::report {
namespace {

calc::Results sample() {
  calc::Results r;
  r.project = "demo";
  r.plan.near_switch = nearfield::NearFieldSwitch::never;
  calc::SceneNote left_out;
  left_out.kind = calc::SceneNote::Kind::observers_left_out;
  left_out.observers = 2;
  r.plan.scene_notes = {left_out};
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 2.0, 1.0, 0.5);
  s.E_direct.assign(s.grid.points.size(), 80.0);
  s.E_indirect.assign(s.grid.points.size(), 16.0);
  s.E.assign(s.grid.points.size(), 96.0);
  s.stats = calc::compute_statistics(s.E);
  r.surfaces.push_back(s);
  r.timing_s = {{"load", 0.01}, {"direct", 0.02}};
  return r;
}

TEST(ResultsJson, HasTheDocumentedShape) {
  const auto j = results_to_json(sample());
  EXPECT_EQ(j["format"], "luxgrid-results/2");
  EXPECT_EQ(j["project"], "demo");
  EXPECT_EQ(j["values"], "maintained");
  // The plan as values (docs/project-format.md, "The plan"), with its summary in words.
  for (const char* k : {"summary",           "quality",           "promise",
                        "near_model",        "near_switch",       "near_switch_reason",
                        "direct_counts",     "pairs_unreachable", "near_far",
                        "intensity_lookups", "indirect_decision", "emergency_direct_only",
                        "refinements",       "visibility",        "scene_notes",
                        "indirect_notes",    "indirect_warnings", "direct_estimated",
                        "errors_estimated",  "estimates"})
    EXPECT_TRUE(j["plan"].contains(k)) << k;
  EXPECT_EQ(j["plan"].size(), 20u);
  // Reflected light did not run: its key is left out, not null (docs/reliability.md).
  EXPECT_FALSE(j["plan"].contains("indirect_run"));
  EXPECT_EQ(j["plan"]["near_switch"], "never");
  EXPECT_EQ(j["plan"]["scene_notes"][0]["kind"], "observers_left_out");
  EXPECT_EQ(j["plan"]["scene_notes"][0]["observers"], 2);
  const auto& s = j["surfaces"][0];
  EXPECT_EQ(s["name"], "wp");
  EXPECT_EQ(s["kind"], "grid");
  EXPECT_EQ(s["size"], nlohmann::json::array({4, 2}));
  ASSERT_EQ(s["points"].size(), 8u);
  // Row-major along u first: the second point is one cell further along u.
  EXPECT_EQ(s["points"][0], nlohmann::json::array({0.25, 0.25, 0.8}));
  EXPECT_EQ(s["points"][1], nlohmann::json::array({0.75, 0.25, 0.8}));
  EXPECT_EQ(s["normals"][0], nlohmann::json::array({0.0, 0.0, 1.0}));
  for (const char* k : {"E", "E_direct", "E_indirect"}) EXPECT_EQ(s[k].size(), 8u) << k;
  for (const char* k : {"Emin", "Eavg", "Emax", "U0", "Ud"})
    EXPECT_TRUE(s["stats"].contains(k)) << k;
  EXPECT_DOUBLE_EQ(s["stats"]["U0"].get<double>(), 1.0);
  // Times are not results: they go to timing.json, so identical runs give identical results.json.
  EXPECT_FALSE(j.contains("timing_s"));
  EXPECT_DOUBLE_EQ(timing_to_json(sample())["timing_s"]["direct"].get<double>(), 0.02);
  EXPECT_EQ(s["quantity"], "planar");
  EXPECT_EQ(s["points_outside"], 0);
  EXPECT_EQ(s["points_in_obstacles"], 0);
  EXPECT_EQ(j["warnings"], nlohmann::json::array());
}

TEST(ResultsJson, SaysWhatGeometryDid) {
  calc::Results r = sample();
  auto& g = r.surfaces[0].grid;
  g.quantity = geometry::Quantity::cylindrical;
  g.active = {true, false, false, true, true, true, false, true};
  g.points_outside = 2;
  g.points_in_obstacles = 1;
  const auto j =
      results_to_json(r, {"room \"L\": the outline is clockwise; reversed to counter-clockwise"});
  const auto& s = j["surfaces"][0];
  EXPECT_EQ(s["quantity"], "cylindrical");
  EXPECT_EQ(s["points_outside"], 2);
  EXPECT_EQ(s["points_in_obstacles"], 1);
  EXPECT_EQ(s["active"],
            nlohmann::json::array({true, false, false, true, true, true, false, true}));
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_EQ(j["warnings"][0],
            "room \"L\": the outline is clockwise; reversed to counter-clockwise");
}

TEST(ResultsJson, SaysWhereTheResultsCameFrom) {
  calc::Results r = sample();
  r.quality = calc::Quality::high;
  r.maintenance_factor = 0.8;
  const auto j = results_to_json(r, {}, {"1.2.3", "ab12"});
  EXPECT_EQ(j["luxgrid_version"], "1.2.3");
  EXPECT_EQ(j["project_sha256"], "ab12");
  EXPECT_EQ(j["quality"], "high");
  EXPECT_DOUBLE_EQ(j["maintenance_factor"].get<double>(), 0.8);
  // The parts add up to the total at every point: all three are maintained values.
  const auto& s = j["surfaces"][0];
  for (size_t i = 0; i < s["E"].size(); ++i)
    EXPECT_DOUBLE_EQ(s["E_direct"][i].get<double>() + s["E_indirect"][i].get<double>(),
                     s["E"][i].get<double>());
}

TEST(ResultsJson, StreamedFileIsTheDocumentByteForByte) {
  // results.json is streamed (write_results_json) rather than dumped from the whole document; the
  // bytes must be the same. Numbers that stress the formatting: integers (written "96.0"), -0.0,
  // exponents both ways, the shortest round trip of 0.1 and of a 17-digit value; inactive points;
  // a second surface with no points ("[]"); a user string that imitates a placeholder; and keys a
  // caller adds to the outline after it is built.
  calc::Results r = sample();
  r.project = "demo \x01points 0 3\n  \"E\": \"\x01points 0 3\"";
  auto& s = r.surfaces[0];
  s.grid.active = {true, false, false, true, true, true, false, true};
  s.E = {96.0, -0.0, 1e-5, 1.5e20, 0.1, 1.0 / 3.0, 123456.789, 2.5e-300};
  s.grid.points[3] = {-1e-7, 12345678901234567.0, 0.8};
  calc::SurfaceResult empty;
  empty.grid.name = "none";
  empty.grid.kind = geometry::SurfaceGrid::Kind::points;
  r.surfaces.push_back(empty);
  nlohmann::json whole = results_to_json(r, {"w"}, {"1.2.3", "ab"});
  nlohmann::json outline = results_outline_json(r, {"w"}, {"1.2.3", "ab"});
  for (auto* j : {&whole, &outline}) {
    (*j)["maintenance"] = {{"factor", 0.8}};
    (*j)["surfaces"][0]["requirements"].push_back({{"what", "Eavg"}, {"met", true}});
  }
  std::ostringstream streamed;
  write_results_json(streamed, outline, r);
  EXPECT_EQ(streamed.str(), whole.dump(1) + "\n");
  // The outline itself holds no point arrays: that is where the memory goes for large grids.
  EXPECT_TRUE(outline["surfaces"][0]["E"].is_string());
}

TEST(Sha256, MatchesThePublishedVectors) {
  // FIPS 180-4 examples (NIST's SHA256.pdf): "abc", the empty string, and the two-block message
  // "abcdbcde...nopq" (56 bytes: its padding needs a second block).
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // A million 'a's: 15 625 blocks (the standard's long example).
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(ColourScale, NiceValues) {
  EXPECT_DOUBLE_EQ(nice_ceil(480.0), 500.0);
  EXPECT_DOUBLE_EQ(nice_ceil(500.0), 500.0);
  EXPECT_DOUBLE_EQ(nice_ceil(501.0), 1000.0);
  EXPECT_DOUBLE_EQ(nice_ceil(0.013), 0.02);
  EXPECT_DOUBLE_EQ(nice_ceil(210.0), 250.0);
  const auto s = auto_scale(480.0);
  ASSERT_FALSE(s.ticks.empty());
  EXPECT_DOUBLE_EQ(s.ticks.front(), 0.0);
  EXPECT_DOUBLE_EQ(s.ticks.back(), 500.0);
}

}  // namespace
}  // namespace luxgrid::report
