// TILT=INCLUDE applied for the luminaire's actual tilt in the scene.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/direct.h"
#include "calc/luminaire_tilt.h"
#include "project/project_file.h"

namespace luxgrid::calc {
namespace {

TEST(LuminaireTilt, AnglesFollowTheLampGeometry) {
  const glm::dmat3 tilt30y = rotation_xyz(0, 30 * kDegToRad, 0);
  EXPECT_NEAR(lamp_tilt_deg(glm::dmat3(1.0), 1), 0.0, 1e-12);
  EXPECT_NEAR(lamp_tilt_deg(tilt30y, 1), 30.0, 1e-12);
  EXPECT_NEAR(lamp_tilt_deg(tilt30y, 2), 30.0, 1e-12);  // x axis tips up by 30 deg about y
  EXPECT_NEAR(lamp_tilt_deg(tilt30y, 3), 0.0, 1e-12);   // the y axis stays horizontal
  EXPECT_NEAR(lamp_tilt_deg(rotation_xyz(0, 0, 1.0), 1), 0.0, 1e-12);  // turning about z: no tilt
}

TEST(LuminaireTilt, TiltTableScalesTheLuminaire) {
  // The corpus file with TILT=INCLUDE; compare the same luminaire untilted and tilted.
  const std::string file = std::string(LUXGRID_SOURCE_DIR) +
                           "/tests/data/photometry/ies/synthetic_tilt_include_lm02.ies";
  auto doc = nlohmann::json::parse(R"({
    "format": "luxgrid-project/1", "name": "tilt",
    "settings": {"indirect": "off", "near_field": "never"},
    "photometry": {"t": ""},
    "rooms": [ { "name": "r", "outline": [[0,0],[4,0],[4,4],[0,4]], "height": 3 } ],
    "luminaires": [ { "photometry": "t", "position": [2, 2, 3] },
                    { "photometry": "t", "position": [2, 2, 3], "rotation": [0, 40, 0] } ],
    "surfaces": [ { "name": "p", "points": [ {"at": [2, 2, 0], "normal": [0, 0, 1]} ] } ]
  })");
  doc["photometry"]["t"] = file;
  Scene scene = project::parse_project(doc, "p.json", "/").scene;
  const auto& ph = scene.photometry.at("t");
  ASSERT_TRUE(ph.tilt) << "the fixture must carry a tilt table";
  // parse_project applies the tilt factors itself (no explicit call here: loading a project
  // must be enough).
  const double expected_ratio = ph.tilt->factor_at(40.0) / ph.tilt->factor_at(0.0);
  // Same direction in the luminaire frame for both: straight down the luminaire's own axis.
  const Vec3 down(0, 0, -1);
  const double i0 = scene.luminaires[0].distribution->intensity(down);
  const double i40 = scene.luminaires[1].distribution->intensity(down);
  ASSERT_GT(i0, 0.0);
  EXPECT_NEAR(i40 / i0, expected_ratio, 1e-12);
  EXPECT_NE(expected_ratio, 1.0) << "pick an angle where the table is not flat";
}

}  // namespace
}  // namespace luxgrid::calc
