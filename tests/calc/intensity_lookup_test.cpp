// The intensity lookup of the far field and the first bounce (calc/intensity_lookup.h): the
// texture's measured bound is a bound, a sharp beam keeps its table, a texture the quality
// accepts keeps far-field E within its limit of the table's, the far-field run loop of
// calc/direct.cpp computes the pair model's sums, and the plan says what each file used.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "calc/direct.h"
#include "calc/intensity_lookup.h"
#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "calc/pipeline.h"
#include "calc/scaled_distribution.h"
#include "photometry/builtin.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

using photometry::DistributionPtr;
using photometry::DistributionTexture;

const std::filesystem::path kData =
    std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry";

DistributionPtr file(const char* rel) {
  return photometry::load_photometry_file(kData / rel).distribution;
}

// A smooth distribution tabulated every degree (bilinear): I = 1000 (1 - 0.5 z)(1 + 0.2 (x^2 -
// y^2)), smooth on the sphere, poles included. Its interpolant's kinks are small (the slope
// changes by about f'' x 1 deg at each measured angle), so a texture follows it closely.
DistributionPtr smooth_table() {
  photometry::SphericalGrid grid;
  for (int c = 0; c < 360; ++c) grid.c_rad.push_back(c * kPi / 180.0);
  for (int g = 0; g <= 180; ++g) grid.gamma_rad.push_back(g * kPi / 180.0);
  for (double c : grid.c_rad)
    for (double g : grid.gamma_rad)
      grid.cd.push_back(1000.0 * (1.0 + 0.5 * std::cos(g)) *
                        (1.0 + 0.2 * std::pow(std::sin(g), 2) * std::cos(2.0 * c)));
  return std::make_shared<photometry::TabularDistribution>(std::move(grid));
}

std::vector<Vec3> random_directions(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Vec3> out(static_cast<size_t>(n));
  for (Vec3& d : out) d = glm::normalize(Vec3(normal(rng), normal(rng), normal(rng)));
  return out;
}

TEST(IntensityLookup, MeasuredBoundHoldsAtRandomDirections) {
  // The open plan's file, a full-sphere file, a large file and the smooth table.
  const std::pair<const char*, DistributionPtr> cases[] = {
      {"mirel", file("ldt/zumtobel_mirel_isym4.ldt")},
      {"deliver", file("ies/deliver_indoor_full360_lm02.ies")},
      {"sample18", file("ldt/sample18_mc360_large.ldt")},
      {"smooth", smooth_table()}};
  for (const auto& [name, source] : cases) {
    const DistributionTexture tex(*source, kTextureCCells, kTextureGammaCells);
    const TextureDeviation dev = texture_deviation(tex, *source);
    double max_cd = 0.0;
    for (int j = 0; j <= kTextureGammaCells; ++j)
      for (int i = 0; i < kTextureCCells; ++i)
        max_cd = std::max(max_cd, tex.intensity(DistributionTexture::texel_direction(
                                      i, j, kTextureCCells, kTextureGammaCells)));
    const double floor_cd = kTextureDeviationFloor * max_cd;
    double worst = 0.0;
    for (const Vec3& d : random_directions(300000, 7)) {
      const double exact = source->intensity(d);
      worst = std::max(worst, std::abs(tex.intensity(d) - exact) / std::max(exact, floor_cd));
    }
    // Margin: 0.1 % of the bound, plus 1e-6 for the texels' float rounding (6e-8 relative).
    EXPECT_LE(worst, dev.bound * 1.001 + 1e-6) << name << ": sampled " << dev.sampled;
  }
}

TEST(IntensityLookup, SharpBeamKeepsTheTable) {
  // A narrow spot: its beam edge is a kink the texture rounds off far beyond 0.1 %.
  const DistributionPtr spot = file("ies/erco_qrcbc35_lm86_spot.ies");
  for (Quality q : {Quality::standard, Quality::high, Quality::reference}) {
    const IntensityLookup l = choose_intensity_lookup(spot, q);
    EXPECT_EQ(l.lookup.get(), spot.get()) << to_string(q);
    EXPECT_EQ(l.texture, nullptr) << to_string(q);
    EXPECT_TRUE(l.choice.kind == IntensityLookupChoice::Kind::table_by_quality ||
                l.choice.kind == IntensityLookupChoice::Kind::table_probe_deviates ||
                l.choice.kind == IntensityLookupChoice::Kind::table_texture_deviates)
        << to_string(q);
  }
  // Draft promises nothing: it takes the texture and says how far off it is.
  const IntensityLookup draft = choose_intensity_lookup(spot, Quality::draft);
  ASSERT_NE(draft.texture, nullptr);
  EXPECT_EQ(draft.lookup.get(), draft.texture.get());
  EXPECT_EQ(draft.choice.kind, IntensityLookupChoice::Kind::texture_draft);
  EXPECT_EQ(draft.choice.c_cells, 1440);
  EXPECT_EQ(draft.choice.gamma_cells, 720);
  EXPECT_GT(draft.choice.deviation, texture_limit(Quality::standard));
}

TEST(IntensityLookup, IntensitiesBeyondAFloatKeepTheTable) {
  // 1e39 cd is infinite in a float texel: no quality may take the texture, draft included.
  photometry::SphericalGrid grid;
  grid.c_rad = {0.0};
  grid.gamma_rad = {0.0, kPi};
  grid.cd = {1e39, 1e39};
  const DistributionPtr huge = std::make_shared<photometry::TabularDistribution>(std::move(grid));
  for (Quality q : {Quality::draft, Quality::standard}) {
    const IntensityLookup l = choose_intensity_lookup(huge, q);
    EXPECT_EQ(l.lookup.get(), huge.get()) << to_string(q);
    EXPECT_EQ(l.texture, nullptr);
    EXPECT_EQ(l.choice.kind, IntensityLookupChoice::Kind::table_float_range);
  }
}

TEST(IntensityLookup, AnalyticProfilesAreTheirOwnLookup) {
  // Exact and cheap already: a texture would only add its float rounding (the validation cases
  // hold analytic sources to 1e-9).
  const DistributionPtr iso = std::make_shared<photometry::IsotropicDistribution>(100.0);
  for (Quality q : {Quality::draft, Quality::standard, Quality::high}) {
    const IntensityLookup l = choose_intensity_lookup(iso, q);
    EXPECT_EQ(l.lookup.get(), iso.get());
    EXPECT_EQ(l.texture, nullptr);
  }
}

TEST(IntensityLookup, AcceptedTextureKeepsFarFieldWithinItsLimit) {
  const DistributionPtr table = smooth_table();
  photometry::LuminousOpening opening;  // a point: the far field at every distance
  for (Quality q : {Quality::standard, Quality::high}) {
    const IntensityLookup l = choose_intensity_lookup(table, q);
    ASSERT_NE(l.texture, nullptr) << to_string(q);
    EXPECT_LE(l.bound, texture_limit(q));
    EXPECT_EQ(l.choice.kind, IntensityLookupChoice::Kind::texture_within);
    const glm::dmat3 turned = rotation_xyz(0.3, -0.2, 1.1);
    nearfield::Emitter with_table = nearfield::make_emitter(opening, Vec3(0, 0, 3), turned, table);
    nearfield::Emitter with_texture = with_table;
    with_texture.far_distribution = l.lookup;
    // E on a floor and two walls around the source, 1 m grid.
    std::vector<std::pair<Vec3, Vec3>> receivers;
    for (int i = -10; i <= 10; ++i)
      for (int j = -10; j <= 10; ++j) {
        receivers.push_back({Vec3(i, j, 0.0), Vec3(0, 0, 1)});
        receivers.push_back({Vec3(-10.0, i, 3.0 + 0.25 * j), Vec3(1, 0, 0)});
        receivers.push_back({Vec3(i, 10.0, 3.0 + 0.25 * j), Vec3(0, -1, 0)});
      }
    std::vector<double> e_table, e_texture;
    double e_max = 0.0;
    for (const auto& [p, n] : receivers) {
      e_table.push_back(nearfield::far_field_illuminance(with_table, p, n));
      e_texture.push_back(nearfield::far_field_illuminance(with_texture, p, n));
      e_max = std::max(e_max, e_table.back());
    }
    // E = I g / d^2 with the same g and d: E's relative error is I's, so within the measured
    // bound at every point brighter than 1 % of the maximum (and the quality's limit).
    for (size_t k = 0; k < e_table.size(); ++k)
      EXPECT_LE(std::abs(e_texture[k] - e_table[k]),
                l.bound * std::max(e_table[k], 0.01 * e_max) + 1e-9 * e_max)
          << to_string(q) << " point " << k;
  }
}

TEST(IntensityLookup, FarFieldRunLoopSumsThePairModel) {
  // calc/direct.cpp's loop for "never" (luminaires outside, points inside, the texture called
  // directly) against the pair model summed point by point.
  const DistributionPtr mirel = file("ldt/zumtobel_mirel_isym4.ldt");
  const IntensityLookup draft = choose_intensity_lookup(mirel, Quality::draft);
  photometry::LuminousOpening panel;
  panel.shape = photometry::LuminousOpening::Shape::rectangle;
  panel.length = 0.6, panel.width = 0.3;
  std::vector<nearfield::Emitter> emitters;
  for (int k = 0; k < 7; ++k) {
    nearfield::Emitter e = nearfield::make_emitter(
        k == 3 ? photometry::LuminousOpening{} : panel, Vec3(1.3 * k, 0.7 * (k % 3), 2.8),
        rotation_xyz(0.0, 0.1 * (k % 2), 0.4 * k), mirel);
    if (k % 2 == 0) {  // half on the texture (one with a factor), half on the table
      e.far_distribution = draft.lookup;
      e.far_texture = draft.texture.get();
    }
    if (k == 4) {
      e.far_texture_factor = 0.75;
      e.far_distribution = std::make_shared<ScaledDistribution>(draft.lookup, 0.75);
    }
    emitters.push_back(std::move(e));
  }
  geometry::SurfaceGrid grid;
  grid.name = "g";
  for (int i = 0; i < 150; ++i) {  // more than one run of points, some facing away
    grid.points.emplace_back(0.07 * i, 0.5 + 0.01 * i, i % 5 == 0 ? 1.5 : 0.8);
    grid.normals.emplace_back(i % 5 == 0 ? Vec3(1, 0, 0) : Vec3(0, 0, 1));
    grid.active.push_back(i % 11 != 0);
  }
  Plan plan;
  plan.near_model = nearfield::Model::far_field();
  plan.near_switch = nearfield::NearFieldSwitch::never;
  DirectCounts counts;
  const std::vector<double> E = direct_illuminance(plan, emitters, grid, {}, &counts);
  for (size_t i = 0; i < grid.points.size(); ++i) {
    double sum = 0.0;
    if (grid.active[i])
      for (const auto& e : emitters)
        sum += nearfield::hybrid_illuminance(e, grid.points[i], grid.normals[i], plan.near_model,
                                             plan.near_switch);
    // The same sums; the loop looks the texture up with the unnormalised direction (its
    // coordinates are ratios), which moves the last bits only.
    EXPECT_NEAR(E[i], sum, 1e-12 * std::max(sum, 1.0)) << i;
  }
  size_t active = 0;
  for (bool a : grid.active) active += a;
  EXPECT_EQ(counts.point_sources, active);
  EXPECT_EQ(counts.far, 6 * active);
}

TEST(IntensityLookup, PlanSaysWhatEachFileUsed) {
  // Two luminaires and one point: too few pairs for a texture at any quality. Thirty luminaires
  // over a workplane at 1 cm (150 000 points, 4.5 million pairs): draft takes the texture.
  const auto scene_of =
      [](const std::string& quality, const std::string& luminaires, const std::string& surface) {
        const auto doc = nlohmann::json::parse(R"({
      "format": "luxgrid-project/1", "name": "lookup",
      "settings": {"quality": ")" + quality + R"(", "indirect": "off"},
      "photometry": { "mirel": "photometry/zumtobel_mirel_isym4.ldt" },
      "rooms": [ { "name": "r", "outline": [[0,0],[6,0],[6,4],[0,4]], "height": 3 } ],
      "luminaires": [ { "photometry": "mirel", "array": )" +
                                               luminaires + R"( } ],
      "surfaces": [ )" + surface + R"( ]
    })");
        return project::parse_project(
                   doc, "p.json", std::filesystem::path(LUXGRID_SOURCE_DIR) / "examples/openplan")
            .scene;
      };
  const std::string two = R"({"origin": [2, 2, 3], "count": [2, 1], "spacing": [2, 1]})";
  const std::string one_point =
      R"({ "name": "p", "points": [ {"at": [3, 2, 0.8], "normal": [0, 0, 1]} ] })";
  for (const char* quality : {"draft", "standard"}) {
    const Results r = run_scene(scene_of(quality, two, one_point));
    ASSERT_EQ(r.plan.intensity_lookups.size(), 1u);
    const IntensityLookupPlan& l = r.plan.intensity_lookups[0];
    EXPECT_EQ(l.group.photometry, "mirel");
    EXPECT_EQ(l.group.luminaires, 2u);
    EXPECT_EQ(l.choice.kind, IntensityLookupChoice::Kind::table_few_pairs);
    EXPECT_EQ(l.choice.pairs, 2u);
  }
  const SceneLookups many = choose_intensity_lookups(scene_of(
      "draft", R"({"origin": [0.6, 0.5, 3], "count": [5, 6], "spacing": [1.2, 0.6]})",
      R"({"name": "wp", "workplane": {"room": "r", "height": 0.8, "border": 0.5}, "spacing": 0.01})"));
  ASSERT_EQ(many.plan.size(), 1u);
  EXPECT_EQ(many.plan[0].group.luminaires, 30u);
  EXPECT_EQ(many.plan[0].choice.kind, IntensityLookupChoice::Kind::texture_draft);
  EXPECT_EQ(many.plan[0].choice.c_cells, 1440);
}

}  // namespace
}  // namespace luxgrid::calc
