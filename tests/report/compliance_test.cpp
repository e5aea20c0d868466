// Compliance checks beyond Em and U0: task presets and their override, Ez and modelling, walls
// and ceilings of room_surfaces, UGR_L read from observers surfaces, Ra, and the HTML table.
// Every expected figure is computed by hand from the few values each test builds.
#include <gtest/gtest.h>

#include "calc/statistics.h"
#include "project/task_presets.h"
#include "report/compliance_table.h"
#include "report/requirement_checks.h"
#include "util/error.h"

namespace luxgrid::report {
namespace {

using nlohmann::json;
// The task presets are read with the project (project/task_presets.h).
using project::find_task_preset;
using project::task_preset_keys;
using project::task_presets;
using project::TaskPreset;

// A surface of two points with the given E; stats computed from them.
calc::SurfaceResult surface(const std::string& name, std::vector<double> E,
                            geometry::Quantity q = geometry::Quantity::planar) {
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid(name, {0, 0, 1.2}, {1, 0, 0}, {0, 1, 0}, 2.0, 1.0, 1.0);
  s.grid.quantity = q;
  s.E = std::move(E);
  s.stats = calc::compute_statistics(s.E);
  return s;
}

const RequirementCheck& find(const std::vector<RequirementCheck>& checks,
                             const std::string& surface, const std::string& q) {
  for (const auto& c : checks) {
    if (c.surface == surface && c.quantity == q) return c;
  }
  throw std::runtime_error("no check " + surface + " " + q);
}

std::string error_of(const json& project) {
  try {
    parse_requirements(project, "p.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(TaskPresets, EveryRowCitesItsSourceAndIsPlausible) {
  // Each row names edition, table and reference number; the limits lie where EN 12464-1's
  // tables put them (Em from 20 to 5000 lx, U0 from 0.1 to 0.9, UGR_L from 10 to 30, Ra 20..100).
  ASSERT_GE(task_presets().size(), 7u);
  for (const auto& p : task_presets()) {
    EXPECT_EQ(std::string(p.edition).rfind("EN 12464-1:20", 0), 0u) << p.key;
    EXPECT_NE(std::string(p.table).find("Table"), std::string::npos) << p.key;
    EXPECT_FALSE(std::string(p.reference).empty()) << p.key;
    EXPECT_GE(p.Em_lx, 20.0);
    EXPECT_LE(p.Em_lx, 5000.0);
    EXPECT_GE(p.U0, 0.1);
    EXPECT_LE(p.U0, 0.9);
    EXPECT_GE(p.UGR_L, 10.0);
    EXPECT_LE(p.UGR_L, 30.0);
    EXPECT_GE(p.Ra, 20.0);
    EXPECT_LE(p.Ra, 100.0);
  }
  // The office row as EN 12464-1:2021 prints it (docs/compliance.md: checked against a public
  // copy).
  const TaskPreset* office = find_task_preset("office-writing");
  ASSERT_NE(office, nullptr);
  EXPECT_EQ(office->Em_lx, 500.0);
  EXPECT_EQ(office->U0, 0.60);
  EXPECT_EQ(office->UGR_L, 19.0);
  EXPECT_EQ(office->Ra, 80.0);
  EXPECT_EQ(office->Ez_lx, 150.0);
  EXPECT_EQ(office->Em_wall_lx, 150.0);
  EXPECT_EQ(office->Em_ceiling_lx, 100.0);
}

TEST(Compliance, PresetFillsAndExplicitKeysOverride) {
  // wp: E = {400, 600}: Em 500, U0 0.8. Preset office-writing: Em 500, U0 0.60, UGR_L 19, Ra 80,
  // Ez 150. The explicit Em 450 replaces the preset's 500 (margin +50 lx, not 0).
  const json p = {
      {"surfaces",
       {{{"name", "wp"}, {"requirements", {{"preset", "office-writing"}, {"Em", 450}}}}}}};
  const Requirements req = parse_requirements(p, "p.json");
  const auto& r = req.surfaces.at("wp");
  EXPECT_EQ(r.limits.at("Em"), 450.0);
  EXPECT_EQ(r.from_preset.count("Em"), 0u);
  EXPECT_EQ(r.limits.at("U0"), 0.60);
  EXPECT_EQ(r.from_preset.at("U0"),
            "office-writing: EN 12464-1:2021 Table 5.26 Offices, ref. 5.26.2");
  EXPECT_EQ(r.limits.at("UGR_L"), 19.0);
  EXPECT_EQ(r.limits.at("Ez"), 150.0);

  calc::Results results;
  results.surfaces.push_back(surface("wp", {400, 600}));
  const auto checks = check_requirements(results, req, {82.0, "photometry \"a\": Ra 82"});
  const auto& em = find(checks, "wp", "Em");
  EXPECT_TRUE(em.met);
  EXPECT_DOUBLE_EQ(em.margin, 50.0);
  EXPECT_TRUE(em.source.empty());
  EXPECT_NEAR(find(checks, "wp", "U0").margin, 0.2, 1e-12);  // 0.8 - 0.6
  const auto& ra = find(checks, "wp", "Ra");
  EXPECT_TRUE(ra.met);
  EXPECT_DOUBLE_EQ(ra.margin, 2.0);  // 82 - 80
  // No observers surface, no cylindrical surface: shown, not met, not calculated.
  for (const char* q : {"UGR_L", "Ez"}) {
    const auto& c = find(checks, "wp", q);
    EXPECT_FALSE(c.calculated) << q;
    EXPECT_FALSE(c.met) << q;
  }
  EXPECT_FALSE(all_met(checks));
  const json j = check_to_json(find(checks, "wp", "UGR_L"));
  EXPECT_EQ(j["calculated"], false);
  EXPECT_TRUE(j["achieved"].is_null());
  EXPECT_EQ(j["limit"], "max");
}

TEST(Compliance, UnknownPresetListsTheKeys) {
  const json p = {{"surfaces", {{{"name", "wp"}, {"requirements", {{"preset", "office"}}}}}}};
  EXPECT_EQ(error_of(p),
            "p.json /surfaces/0/requirements/preset: unknown preset \"office\", expected " +
                task_preset_keys());
}

TEST(Compliance, UgrFromObserversSurfaces) {
  // UGR_L 19 against observers surfaces with UGR_max 17.2 and 18.4: the largest (18.4) counts,
  // margin 19 - 18.4 = 0.6. Naming only "eyes a" takes 17.2 (margin 1.8).
  calc::Results results;
  results.surfaces.push_back(surface("wp", {400, 600}));
  auto a = surface("eyes a", {0, 0});
  a.grid.kind = geometry::SurfaceGrid::Kind::observers;
  a.UGR_max = 17.2;
  auto b = surface("eyes b", {0, 0});
  b.grid.kind = geometry::SurfaceGrid::Kind::observers;
  b.UGR_max = 18.4;
  results.surfaces.push_back(a);
  results.surfaces.push_back(b);
  const json all = {{"surfaces",
                     {{{"name", "wp"}, {"requirements", {{"UGR_L", 19}}}},
                      {{"name", "eyes a"}},
                      {{"name", "eyes b"}}}}};
  const auto c1 = check_requirements(results, parse_requirements(all, "p.json"));
  ASSERT_EQ(c1.size(), 1u);
  EXPECT_TRUE(c1[0].calculated);
  EXPECT_TRUE(c1[0].upper_limit);
  EXPECT_DOUBLE_EQ(c1[0].achieved, 18.4);
  EXPECT_NEAR(c1[0].margin, 0.6, 1e-12);
  json named = all;
  named["surfaces"][0]["requirements"]["glare_observers"] = "eyes a";
  const auto c2 = check_requirements(results, parse_requirements(named, "p.json"));
  EXPECT_DOUBLE_EQ(c2[0].achieved, 17.2);
  EXPECT_TRUE(c2[0].met);
  // 18.4 above a limit of 18: not met, margin -0.4.
  json strict = all;
  strict["surfaces"][0]["requirements"]["UGR_L"] = 18;
  const auto c3 = check_requirements(results, parse_requirements(strict, "p.json"));
  EXPECT_FALSE(c3[0].met);
  EXPECT_NEAR(c3[0].margin, -0.4, 1e-12);
  // A named surface that is not an observers surface: not calculated, saying why.
  named["surfaces"][0]["requirements"]["glare_observers"] = "wp";
  const auto c4 = check_requirements(results, parse_requirements(named, "p.json"));
  EXPECT_FALSE(c4[0].calculated);
  EXPECT_NE(c4[0].note.find("gives no UGR"), std::string::npos) << c4[0].note;
}

TEST(Compliance, EzAndModellingPointByPoint) {
  // Horizontal "h": Eh = {400, 500}; cylindrical "z" on the same points: Ez = {160, 250}.
  // Ratios 0.40 and 0.50: within [0.3, 0.6], margin min(0.40 - 0.3, 0.6 - 0.50) = 0.10.
  // Ez = Eavg of z = 205 lx >= 150 (margin 55 lx).
  calc::Results results;
  results.surfaces.push_back(surface("h", {400, 500}, geometry::Quantity::horizontal));
  results.surfaces.push_back(surface("z", {160, 250}, geometry::Quantity::cylindrical));
  const json p = {{"surfaces",
                   {{{"name", "h"},
                     {"quantity", "horizontal"},
                     {"requirements", {{"Ez", 150}, {"cylindrical", "z"}}}},
                    {{"name", "z"},
                     {"quantity", "cylindrical"},
                     {"requirements", {{"modelling", {0.3, 0.6}}, {"horizontal", "h"}}}}}}};
  const auto checks = check_requirements(results, parse_requirements(p, "p.json"));
  const auto& ez = find(checks, "h", "Ez");
  EXPECT_DOUBLE_EQ(ez.achieved, 205.0);
  EXPECT_DOUBLE_EQ(ez.margin, 55.0);
  const auto& m = find(checks, "z", "modelling");
  EXPECT_DOUBLE_EQ(m.achieved, 0.40);
  EXPECT_DOUBLE_EQ(*m.achieved_max, 0.50);
  EXPECT_NEAR(m.margin, 0.10, 1e-12);
  EXPECT_TRUE(m.met);
  // A ratio of 0.25 at one point (Ez 100 over Eh 400) misses the range by 0.05.
  results.surfaces[1].E = {100, 250};
  const auto missed = check_requirements(results, parse_requirements(p, "p.json"));
  const auto& m2 = find(missed, "z", "modelling");
  EXPECT_FALSE(m2.met);
  EXPECT_NEAR(m2.margin, -0.05, 1e-12);
  EXPECT_EQ(check_to_json(m2)["limit"], "range");
}

TEST(Compliance, QuantityTheSurfaceDoesNotComputeIsRefused) {
  const json ez = {{"surfaces", {{{"name", "wp"}, {"requirements", {{"Ez", 150}}}}}}};
  EXPECT_EQ(error_of(ez),
            "p.json /surfaces/0/requirements/Ez: surface \"wp\" computes planar illuminance, so it "
            "cannot give Ez; give it "
            "\"quantity\": \"cylindrical\", or name a cylindrical surface with \"cylindrical\": "
            "\"<surface>\"");
  const json esc = {
      {"surfaces",
       {{{"name", "z"}, {"quantity", "cylindrical"}, {"requirements", {{"Esc", 50}}}}}}};
  EXPECT_NE(
      error_of(esc).find("surface \"z\" computes cylindrical illuminance, so it cannot give Esc"),
      std::string::npos);
  const json wrong_pair = {
      {"surfaces",
       {{{"name", "wp"}, {"requirements", {{"Ez", 150}, {"cylindrical", "v"}}}},
        {{"name", "v"}, {"quantity", "vertical"}}}}};
  EXPECT_EQ(error_of(wrong_pair),
            "p.json /surfaces/0/requirements/cylindrical: surface \"v\" computes vertical "
            "illuminance, not cylindrical");
  const json modelling_alone = {{"surfaces",
                                 {{{"name", "z"},
                                   {"quantity", "cylindrical"},
                                   {"requirements", {{"modelling", {0.3, 0.6}}}}}}}};
  EXPECT_NE(error_of(modelling_alone).find("cannot give modelling"), std::string::npos);
  const json preset_on_cyl = {{"surfaces",
                               {{{"name", "z"},
                                 {"quantity", "cylindrical"},
                                 {"requirements", {{"preset", "classroom"}}}}}}};
  EXPECT_NE(error_of(preset_on_cyl).find("a task preset belongs on the task area"),
            std::string::npos);
}

TEST(Compliance, WallsAndCeilingsMetAndMissed) {
  // room_surfaces "room": walls 0 and 1, ceiling, floor. Preset walls-and-ceilings: walls Em >= 50,
  // ceiling Em >= 30, both U0 >= 0.10. Wall 0 {40, 80}: Em 60, U0 40/60 = 0.667, met. Wall 1
  // {5, 75}: Em 40 (misses by 10 lx), U0 5/40 = 0.125 (met). Ceiling {2, 58}: Em 30 exactly (met),
  // U0 2/30 = 0.0667 (misses by 0.0333). The floor has no requirement: no check.
  calc::Results results;
  results.surfaces.push_back(surface("room floor", {100, 100}));
  results.surfaces.push_back(surface("room ceiling", {2, 58}));
  results.surfaces.push_back(surface("room wall 0", {40, 80}));
  results.surfaces.push_back(surface("room wall 1", {5, 75}));
  const json p = {{"surfaces",
                   {{{"name", "room"},
                     {"room_surfaces", {{"room", "r"}}},
                     {"requirements", {{"preset", "walls-and-ceilings"}}}}}}};
  const auto checks = check_requirements(results, parse_requirements(p, "p.json"));
  ASSERT_EQ(checks.size(), 6u);
  EXPECT_EQ(find(checks, "room ceiling", "Em").role, "ceiling");
  EXPECT_TRUE(find(checks, "room ceiling", "Em").met);
  EXPECT_FALSE(find(checks, "room ceiling", "U0").met);
  EXPECT_NEAR(find(checks, "room ceiling", "U0").margin, 2.0 / 30.0 - 0.10, 1e-12);
  EXPECT_EQ(find(checks, "room wall 0", "Em").role, "wall");
  EXPECT_TRUE(find(checks, "room wall 0", "Em").met);
  EXPECT_TRUE(find(checks, "room wall 0", "U0").met);
  EXPECT_FALSE(find(checks, "room wall 1", "Em").met);
  EXPECT_DOUBLE_EQ(find(checks, "room wall 1", "Em").margin, -10.0);
  EXPECT_TRUE(find(checks, "room wall 1", "U0").met);
  EXPECT_FALSE(all_met(checks));

  // A task preset gives its own wall and ceiling values (office: 150 and 100 lx); explicit
  // "walls" override them, and a preset without such values is refused.
  const json office = {
      {"surfaces",
       {{{"name", "room"},
         {"room_surfaces", {{"room", "r"}}},
         {"requirements", {{"preset", "office-writing"}, {"walls", {{"Em", 75}}}}}}}}};
  const auto req = parse_requirements(office, "p.json");
  EXPECT_EQ(req.walls.at("room").limits.at("Em"), 75.0);
  EXPECT_EQ(req.walls.at("room").limits.at("U0"), 0.10);
  EXPECT_EQ(req.surfaces.at("room ceiling").limits.at("Em"), 100.0);
  const json corridor = {{"surfaces",
                          {{{"name", "room"},
                            {"room_surfaces", {{"room", "r"}}},
                            {"requirements", {{"preset", "corridor"}}}}}}};
  EXPECT_NE(error_of(corridor).find("gives no wall and ceiling illuminance"), std::string::npos);
}

TEST(Compliance, TableShowsEveryRowWithItsResult) {
  calc::Results results;
  results.surfaces.push_back(surface("wp", {400, 600}));
  const json p = {
      {"surfaces", {{{"name", "wp"}, {"requirements", {{"preset", "office-writing"}}}}}}};
  const auto checks = check_requirements(results, parse_requirements(p, "p.json"),
                                         {std::nullopt, "unknown: no CRI"});
  const std::string h = compliance_table_html(checks);
  EXPECT_NE(h.find("data-check=\"wp|Em\" data-result=\"met\""), std::string::npos);
  EXPECT_NE(h.find("data-check=\"wp|UGR_L\" data-result=\"not calculated\""), std::string::npos);
  EXPECT_NE(h.find("data-check=\"wp|Ra\" data-result=\"not calculated\""), std::string::npos);
  EXPECT_NE(h.find("unknown: no CRI"), std::string::npos);
  EXPECT_NE(h.find("EN 12464-1:2021 Table 5.26 Offices, ref. 5.26.2"), std::string::npos);
  EXPECT_NE(h.find("data-requirements=\"not met\""), std::string::npos);
  EXPECT_EQ(compliance_table_html({}), "");
}

}  // namespace
}  // namespace luxgrid::report
