// The checking-tool warnings of photometry/file_warnings.h, each with its exact text on a small
// synthetic file, on both sides of its threshold; the flux conventions a file states; and the
// intensity limit keeping a read distribution's flux finite.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "photometry/derived_photometry.h"
#include "photometry/limits.h"
#include "photometry/photometry.h"

namespace luxgrid::photometry {
namespace {

// LM-63-2002, type C, vertical angles `v`, horizontal angles `h`, values plane by plane.
std::string ies(const std::string& lumens, const std::string& v, const std::string& h,
                const std::string& values, int nv, int nh, const std::string& lamps = "1") {
  return "IESNA:LM-63-2002\n[TEST] validation\nTILT=NONE\n" + lamps + " " + lumens + " 1 " +
         std::to_string(nv) + " " + std::to_string(nh) + " 1 2 0 0 0\n1 1 10\n" + v + "\n" + h +
         "\n" + values + "\n";
}

// EULUMDAT, Isym 1, gamma 0, 90, 180 all at `cd_per_klm`, 1000 lm lamp flux (count `lamps`).
std::string ldt(const std::string& dff, const std::string& lor, const std::string& lamps = "1",
                const std::string& cd_per_klm = "70") {
  // Lines 1-21: header, names, dimensions; 22-26: DFF, LOR, conversion, tilt, one lamp set.
  std::vector<std::string> l = {"luxgrid tests", "1", "1", "1", "0", "3", "90", "", "ratios"};
  for (const char* x : {"", "", "", "100", "0", "50", "80", "0", "0", "0", "0", "0"})
    l.push_back(x);
  for (const std::string& x : {dff, lor, std::string("1"), std::string("0"), std::string("1")})
    l.push_back(x);
  for (const std::string& x : {lamps, std::string("LED"), std::string("1000"), std::string("3000"),
                               std::string("80"), std::string("10")})
    l.push_back(x);
  for (int k = 0; k < 10; ++k) l.push_back("0.5");
  for (const char* a : {"0", "0", "90", "180"}) l.push_back(a);
  for (int k = 0; k < 3; ++k) l.push_back(cd_per_klm);
  std::string s;
  for (const auto& x : l) s += x + "\n";
  return s;
}

std::vector<std::string> warnings_of(const std::string& text, const std::string& name) {
  return load_photometry_text(text, name).warnings;
}

using Warnings = std::vector<std::string>;

// One synthetic type C file per case: its vertical and horizontal angles and values, and the
// exact warnings it must give (none on the quiet side of a threshold).
struct PlaneCase {
  const char* name;
  const char* v;
  const char* h;
  const char* values;
  int nv, nh;
  Warnings expected;
};

// One case a row reads as a table:
// clang-format off
const PlaneCase kPlaneCases[] = {
    {"pole.ies", "0 45 90", "0 90 180", "100 50 0 110 50 0 105 50 0", 3, 3,
     {"pole.ies: the C planes disagree at gamma 0 (100 to 110 cd, 10.0 %); the pole is taken as "
      "their mean"}},
    // An upper pole too, when the table reaches gamma 180.
    {"up.ies", "0 90 180", "0 90 180", "0 0 100 0 0 100 0 0 90", 3, 3,
     {"up.ies: the C planes disagree at gamma 180 (90 to 100 cd, 11.1 %); the pole is taken as "
      "their mean"}},
    // A dark plane at the pole: no percentage of zero.
    {"dark.ies", "0 45 90", "0 90 180", "0 50 0 4 50 0 0 50 0", 3, 3,
     {"dark.ies: the C planes disagree at gamma 0 (0 to 4 cd); the pole is taken as their mean"}},
    // Rounding spreads under 2 % of the larger value stay quiet.
    {"round.ies", "0 45 90", "0 90 180", "100 50 0 101.9 50 0 101 50 0", 3, 3, {}},
    {"down.ies", "0 45 90", "0", "100 50 10", 3, 1,
     {"down.ies: the table ends at gamma 90 with intensities up to 10 cd there (10.0 % of the "
      "maximum); the light is cut off abruptly at the horizon"}},
    {"uplight.ies", "90 135 180", "0", "4 50 100", 3, 1,
     {"uplight.ies: the table starts at gamma 90 with intensities up to 4 cd there (4.0 % of the "
      "maximum); the light is cut off abruptly at the horizon"}},
    // Stray light under 1 % of the maximum is what every goniometer sees at the horizon.
    {"stray.ies", "0 45 90", "0", "100 50 0.9", 3, 1, {}},
    // A table that goes on past 90 states no cut-off.
    {"full.ies", "0 90 180", "0", "100 50 10", 3, 1, {}},
};
// clang-format on

TEST(PlaneWarnings, PoleAndCutOffOnBothSidesOfTheirThresholds) {
  for (const PlaneCase& c : kPlaneCases)
    EXPECT_EQ(warnings_of(ies("-1", c.v, c.h, c.values, c.nv, c.nh), c.name), c.expected) << c.name;
}

TEST(PoleWarning, TheCorpusIsym3FileDisagreesByWhatItsTableSays) {
  const Photometry p = load_photometry_file(
      std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ldt/synthetic_isym3_c90c270.ldt");
  ASSERT_FALSE(p.warnings.empty());
  EXPECT_NE(p.warnings.front().find("synthetic_isym3_c90c270.ldt: the C planes disagree at gamma 0 "
                                    "(2200 to 2866 cd, 30.3 %); the pole is taken as their mean"),
            std::string::npos)
      << p.warnings.front();
}

TEST(StatedRatioWarning, LorAndDffMoreThanTwoPointsFromTheIntegral) {
  // 70 cd/klm everywhere: 4 pi x 70 = 879.6 lm of 1000 lm, LOR 87.96 %, DFF 50 %.
  EXPECT_EQ(warnings_of(ldt("50", "91"), "lor.ldt"),
            Warnings{"lor.ldt: the stated LOR (91.0 %) differs from the integrated 88.0 % by 3.0 "
                     "percentage points"});
  EXPECT_EQ(warnings_of(ldt("45", "89"), "dff.ldt"),
            Warnings{"dff.ldt: the stated DFF (45.0 %) differs from the integrated 50.0 % by 5.0 "
                     "percentage points"});
  EXPECT_EQ(warnings_of(ldt("51.9", "89.9"), "ok.ldt"), Warnings{});
  // Absolute photometry has no lamp flux, hence no integrated LOR to compare; DFF still counts.
  EXPECT_EQ(warnings_of(ldt("50", "10", "-1"), "abs.ldt"), Warnings{});
}

TEST(FluxConvention, IsNamedForEachWayAFileStatesIt) {
  EXPECT_EQ(load_photometry_text(ies("-1", "0 90", "0", "10 0", 2, 1), "a.ies").flux_convention,
            "absolute photometry (IES lumens per lamp = -1)");
  EXPECT_EQ(
      load_photometry_text(ies("1000", "0 90", "0", "10 0", 2, 1, "2"), "r.ies").flux_convention,
      "relative photometry (IES: 2 x 1000 lm rated lamp flux)");
  EXPECT_EQ(load_photometry_text(ldt("50", "88", "-1"), "a.ldt").flux_convention,
            "absolute photometry (EULUMDAT lamp count -1 < 0; 1000 lm is the luminaire flux)");
  EXPECT_EQ(load_photometry_text(ldt("50", "88"), "r.ldt").flux_convention,
            "relative photometry (EULUMDAT: 1 lamp, 1000 lm rated lamp flux)");
  const Photometry none =
      load_photometry_text(ies("1000", "0 90", "0", "10 0", 2, 1, "0"), "z.ies");
  EXPECT_FALSE(none.lamp_flux_lm);
  EXPECT_EQ(none.flux_convention,
            "absolute photometry (IES: 0 lamps, read as lumens per lamp = -1)");
  EXPECT_EQ(none.warnings,
            Warnings{"z.ies:4: 0 lamps of 1000 lm give no lamp flux; read as absolute "
                     "photometry"});
}

TEST(IntensityLimit, AFileAtTheLimitReadsWithAFiniteFlux) {
  const Photometry p =
      load_photometry_text(ies("-1", "0 90 180", "0", "1e9 1e9 1e9", 3, 1), "max.ies");
  const DerivedPhotometry d = derive(p);
  EXPECT_NEAR(d.flux_lm, 4 * kPi * kMaxIntensity_cd, 1e-9 * d.flux_lm);
  EXPECT_EQ(d.max_cd, kMaxIntensity_cd);
}

// The corpus stays quiet: of its 66 files, only these give a checking-tool warning, each for a
// reason its MANIFEST row or the comments of file_warnings.cpp give.
TEST(CorpusWarnings, OnlyTheFilesThatDeserveOne) {
  const std::filesystem::path dir =
      std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry";
  std::vector<std::string> got;
  for (const char* sub : {"ies", "ldt"})
    for (const auto& e : std::filesystem::directory_iterator(dir / sub)) {
      for (const std::string& w : load_photometry_file(e.path()).warnings)
        for (const char* kind : {"disagree at gamma", "cut off abruptly", ": the stated "})
          if (w.find(kind) != std::string::npos)
            got.push_back(e.path().filename().string() + ": " + kind);
    }
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, (Warnings{
                     "sample06_spot_coarse.ldt: : the stated ",            // LOR 100.1 % vs 102.5 %
                     "synthetic_isym3_c90c270.ldt: cut off abruptly",      // 24.5 % at gamma 90
                     "synthetic_isym3_c90c270.ldt: disagree at gamma",     // 2200 to 2866 cd
                     "synthetic_multiple_lamp_sets.ldt: : the stated ",    // LOR 100 % vs 90.5 %
                     "synthetic_tilt_include_lm02.ies: cut off abruptly",  // 10 % at gamma 90
                 }));
}

}  // namespace
}  // namespace luxgrid::photometry
