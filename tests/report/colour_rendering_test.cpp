// Ra as photometric files write it: EULUMDAT's CRI field in its usual spellings, CIE groups,
// IES keywords; and the scene's value as the lowest over the entries its luminaires use.
#include <gtest/gtest.h>

#include "report/colour_rendering.h"

namespace luxgrid::report {
namespace {

TEST(ColourRendering, SpellingsOfTheIndex) {
  EXPECT_EQ(parse_colour_rendering("80"), 80.0);
  EXPECT_EQ(parse_colour_rendering(" Ra 82 "), 82.0);
  EXPECT_EQ(parse_colour_rendering(">80"), 80.0);
  EXPECT_EQ(parse_colour_rendering(">=90"), 90.0);
  EXPECT_EQ(parse_colour_rendering("CRI90"), 90.0);
  EXPECT_EQ(parse_colour_rendering("80-89"), 80.0);  // a range states its lower bound
  EXPECT_EQ(parse_colour_rendering("92,5"), 92.5);   // decimal comma
  // CIE groups give their lower bounds [CIE29.2].
  EXPECT_EQ(parse_colour_rendering("1A"), 90.0);
  EXPECT_EQ(parse_colour_rendering("1b"), 80.0);
  EXPECT_EQ(parse_colour_rendering("2B"), 60.0);
  EXPECT_EQ(parse_colour_rendering("4"), 20.0);
  for (const char* bad : {"", "Unknown", "-", "830", "80 lm", "n/a"}) {
    EXPECT_FALSE(parse_colour_rendering(bad).has_value()) << bad;
  }
}

TEST(ColourRendering, FileAndSceneTakeTheLowest) {
  photometry::Photometry a, b;
  a.source = "a.ldt";
  a.lamp_sets = {{1, "LED", 1000, "3000K", "90", 10}, {1, "LED", 1000, "4000K", "82", 10}};
  b.source = "b.ies";
  b.keywords["_CRI"] = "85";
  EXPECT_EQ(photometry_colour_rendering(a), 82.0);
  EXPECT_EQ(photometry_colour_rendering(b), 85.0);

  calc::Scene scene;
  scene.photometry["a"] = a;
  scene.photometry["b"] = b;
  scene.photometry["unused"] = photometry::Photometry{};
  calc::Luminaire la, lb;
  la.photometry = "a";
  lb.photometry = "b";
  scene.luminaires = {la, lb};
  const auto ra = scene_colour_rendering(scene);
  ASSERT_TRUE(ra.Ra.has_value());
  EXPECT_EQ(*ra.Ra, 82.0);
  EXPECT_NE(ra.source.find("\"a\""), std::string::npos) << ra.source;

  // One used entry without a CRI makes the scene's Ra unknown, naming it.
  calc::Luminaire lu;
  lu.photometry = "unused";
  scene.luminaires.push_back(lu);
  const auto unknown = scene_colour_rendering(scene);
  EXPECT_FALSE(unknown.Ra.has_value());
  EXPECT_NE(unknown.source.find("\"unused\""), std::string::npos) << unknown.source;
}

}  // namespace
}  // namespace luxgrid::report
