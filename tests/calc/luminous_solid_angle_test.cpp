// The exact solid angle of a luminous opening (calc/glare/luminous_solid_angle.h) against closed
// forms: a rectangle seen on its axis, 4 asin(ab / sqrt((a^2 + d^2)(b^2 + d^2))) with half-sides
// a, b at distance d; a rectangle seen from above one corner, asin(wl / sqrt((w^2 + d^2)(l^2 +
// d^2))); a disk on its axis, 2 pi (1 - d / sqrt(d^2 + r^2)); never above 2 pi; CIE 117's
// A / d^2 far away. And which eyes lie inside the opening.
#include <gtest/gtest.h>

#include <cmath>

#include "calc/glare/luminous_solid_angle.h"

namespace luxgrid::calc::glare {
namespace {

photometry::LuminousOpening rectangle(double length_m, double width_m, double height_m = 0.0) {
  photometry::LuminousOpening o;
  o.shape = photometry::LuminousOpening::Shape::rectangle;
  o.length = length_m, o.width = width_m, o.height = height_m;
  return o;
}

double on_axis_rectangle_sr(double a, double b, double d) {
  return 4.0 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d)));
}

TEST(LuminousSolidAngle, RectangleOnItsAxis) {
  const auto panel = rectangle(0.6, 0.3);
  for (double d : {1e-3, 1e-2, 0.1, 0.5, 2.0}) {
    EXPECT_NEAR(luminous_solid_angle_sr(panel, {0, 0, -d}), on_axis_rectangle_sr(0.3, 0.15, d),
                1e-12 * on_axis_rectangle_sr(0.3, 0.15, d))
        << d;
  }
  // 1 um below: within 1e-5 of a half sphere, never above it; from above (behind): nothing.
  const double touching = luminous_solid_angle_sr(panel, {0, 0, -1e-6});
  EXPECT_LE(touching, 2 * kPi);
  EXPECT_NEAR(touching, 2 * kPi, 1e-4);
  EXPECT_EQ(luminous_solid_angle_sr(panel, {0, 0, 0.1}), 0.0);
}

TEST(LuminousSolidAngle, RectangleFromAboveACorner) {
  const double w = 0.6, l = 0.3, d = 0.05;
  EXPECT_NEAR(luminous_solid_angle_sr(rectangle(w, l), {-0.3, -0.15, -d}),
              std::asin(w * l / std::sqrt((w * w + d * d) * (l * l + d * d))), 1e-12);
}

TEST(LuminousSolidAngle, FarAwayItIsCie117sAreaOverDistanceSquared) {
  // 100 m below a 0.6 x 0.3 m panel: A / d^2 = 1.8e-5 sr, the exact value within 1e-5 relative
  // (the first correction is of order (size / d)^2).
  EXPECT_NEAR(luminous_solid_angle_sr(rectangle(0.6, 0.3), {0, 0, -100}), 0.18 / 1e4,
              1e-5 * 1.8e-5);
}

TEST(LuminousSolidAngle, DiskOnItsAxis) {
  photometry::LuminousOpening disk;
  disk.shape = photometry::LuminousOpening::Shape::disk;
  disk.length = disk.width = 0.2;
  for (double d : {0.01, 0.05, 0.5}) {
    const double exact = 2 * kPi * (1 - d / std::sqrt(d * d + 0.01));
    // The 256-gon: at most 0.01 % less area, and less than that in solid angle near the disk.
    EXPECT_NEAR(luminous_solid_angle_sr(disk, {0, 0, -d}), exact, 1e-4 * exact) << d;
  }
}

TEST(LuminousSolidAngle, LuminousSidesSeenSideOn) {
  // A 0.6 x 0.3 x 0.2 m box (sides from z = 0 to 0.2) seen from 5 cm beside the middle of its
  // 0.3 x 0.2 m end face (at x = 0.3), level with its middle: that face alone, on its axis.
  const auto box = rectangle(0.6, 0.3, 0.2);
  EXPECT_NEAR(luminous_solid_angle_sr(box, {0.35, 0, 0.1}), on_axis_rectangle_sr(0.15, 0.1, 0.05),
              1e-12);
}

TEST(LuminousSolidAngle, InsideTheOpening) {
  const auto panel = rectangle(0.6, 0.3);
  EXPECT_TRUE(inside_luminous_opening(panel, {0.1, 0, 0}));
  EXPECT_TRUE(inside_luminous_opening(panel, {0.29, 0.14, 1e-10}));
  EXPECT_FALSE(inside_luminous_opening(panel, {0.31, 0, 0}));   // beside it
  EXPECT_FALSE(inside_luminous_opening(panel, {0, 0, -1e-3}));  // 1 mm in front
  const auto box = rectangle(0.6, 0.3, 0.2);
  EXPECT_TRUE(inside_luminous_opening(box, {0, 0, 0.1}));
  EXPECT_FALSE(inside_luminous_opening(box, {0, 0, 0.21}));
  photometry::LuminousOpening point;
  EXPECT_FALSE(inside_luminous_opening(point, {0, 0, 0}));
  EXPECT_EQ(luminous_solid_angle_sr(point, {0, 0, -1}), 0.0);
}

}  // namespace
}  // namespace luxgrid::calc::glare
