// One luminaire's UGR term L^2 omega / p^2 against a brute-force integral of L^2 / p^2 over the
// solid angle of its opening, for random small Lambertian openings in the Guth field.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "calc/glare/guth_position_index.h"
#include "calc/glare/ugr.h"
#include "calc/scene.h"
#include "photometry/builtin.h"

namespace luxgrid::calc::glare {
namespace {

// The sum CIE 117 writes, L^2 omega / p^2, is the small-source limit of the integral of
// L^2 / p(direction)^2 over the source's solid angle: for an opening of size s at distance d the
// two differ at order (s / d)^2 (omega = A cos / d^2 and p, taken at the centre, vary to second
// order across it). Openings of 0.05-0.2 m at 1.5-6 m (s / d <= 0.13) stay within 1 %; the
// brute force uses 80 x 80 cells, whose own midpoint error is ~(s / d / 80)^2, negligible.
TEST(UgrSum, TermMatchesBruteForceIntegralOverTheOpening) {
  std::mt19937 rng(20240517);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const photometry::LambertianDistribution lambert(1500.0);  // cd at nadir
  int checked = 0;
  for (int trial = 0; trial < 200 && checked < 60; ++trial) {
    const double yaw = 2.0 * kPi * u(rng);
    const Vec3 view(std::cos(yaw), std::sin(yaw), 0.0);
    const ViewFrame frame = ViewFrame::looking(view);
    const double R = 1.5 + 4.5 * u(rng), H = R * (0.05 + 1.7 * u(rng)),
                 T = R * (-2.5 + 5.0 * u(rng));
    const Vec3 eye(0.3, -0.2, 1.2);
    Pose pose;
    pose.position = eye + R * frame.forward + T * frame.right + H * frame.up;
    pose.rotation = rotation_xyz(0.0, 0.0, 2.0 * kPi * u(rng));  // facing down, turned about z
    photometry::LuminousOpening o;
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = 0.05 + 0.15 * u(rng);
    o.width = 0.05 + 0.15 * u(rng);
    const auto t = glare_term(lambert, o, pose, eye, frame);
    ASSERT_TRUE(t.has_value());
    // A Lambertian opening has one luminance in every direction: I0 / A.
    const double L = 1500.0 / (o.length * o.width);
    EXPECT_NEAR(t->L_cd_m2 / L, 1.0, 1e-12);
    constexpr int n = 80;
    double brute = 0.0;
    bool whole =
        true;  // every cell inside the field (else the term and the integral differ by design)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const Vec3 local((-0.5 + (i + 0.5) / n) * o.length, (-0.5 + (j + 0.5) / n) * o.width, 0.0);
        const Vec3 c = pose.position + pose.rotation * local;
        const Vec3 d = c - eye;
        const double r = glm::length(d);
        const double cr = glm::dot(d, frame.forward), ch = glm::dot(d, frame.up),
                     ct = glm::dot(d, frame.right);
        if (!in_guth_field(cr, ct, ch)) whole = false;
        const double d_omega =
            (o.length * o.width / (n * n)) * (ch / r) / (r * r);  // cos at the cell = H / r
        const double p = guth_position_index(ch / cr, ct / cr);
        brute += L * L * d_omega / (p * p);
      }
    if (!whole) continue;
    EXPECT_NEAR(t->value() / brute, 1.0, 0.01) << "R " << R << " T " << T << " H " << H;
    ++checked;
  }
  EXPECT_GE(checked, 50);
}

// A source below the line of sight, behind the eye or with the opening turned away adds nothing.
TEST(UgrSum, SourcesOutsideTheFieldOrFacingAwayDoNotCount) {
  const photometry::LambertianDistribution lambert(1000.0);
  photometry::LuminousOpening o;
  o.shape = photometry::LuminousOpening::Shape::rectangle;
  o.length = o.width = 0.6;
  const ViewFrame frame = ViewFrame::looking(Vec3(1, 0, 0));
  const Vec3 eye(0, 0, 1.2);
  Pose pose;
  pose.position = Vec3(3, 0, 1.0);  // below the eye
  EXPECT_FALSE(glare_term(lambert, o, pose, eye, frame));
  pose.position = Vec3(-3, 0, 2.8);  // behind
  EXPECT_FALSE(glare_term(lambert, o, pose, eye, frame));
  pose.position = Vec3(3, 0, 2.8);
  EXPECT_TRUE(glare_term(lambert, o, pose, eye, frame));
  pose.rotation = rotation_xyz(kPi, 0.0, 0.0);  // facing up: the eye sees its back
  EXPECT_FALSE(glare_term(lambert, o, pose, eye, frame));
}

}  // namespace
}  // namespace luxgrid::calc::glare

namespace luxgrid::calc::glare {
namespace {

// A 0.6 x 0.3 m Lambertian panel 0.5 m above an eye looking up at 60 degrees (inside the Guth
// field): A_p / d^2 = 0.72 sr, beyond the 0.1 sr CIE 117 rates. CIE 190's tables keep
// A_p / d^2 (SolidAngleRule::cie117_formula, bit for bit); an observer's term takes the exact
// solid angle of the rectangle on its axis, 4 asin(ab / sqrt((a^2 + d^2)(b^2 + d^2))) with
// half-sides a, b (Omega = 0.5773 sr here), to 1e-9.
TEST(UgrSum, TablesKeepCie117sSolidAngleObserversTakeTheExactOneBeyondItsRange) {
  const photometry::LambertianDistribution lambert(1500.0);
  photometry::LuminousOpening o;
  o.shape = photometry::LuminousOpening::Shape::rectangle;
  o.length = 0.6, o.width = 0.3;
  const Vec3 eye(0.0, 0.0, 1.2);
  Pose pose;
  pose.position = eye + Vec3(0.0, 0.0, 0.5);
  const ViewFrame frame = ViewFrame::looking(Vec3(0.5, 0.0, std::sqrt(3.0) / 2.0));
  const auto formula = glare_term(lambert, o, pose, eye, frame, SolidAngleRule::cie117_formula);
  const auto exact = glare_term(lambert, o, pose, eye, frame);
  ASSERT_TRUE(formula.has_value());
  ASSERT_TRUE(exact.has_value());
  EXPECT_EQ(formula->omega_sr, 0.6 * 0.3 / 0.25);
  const double a = 0.3, b = 0.15, d = 0.5;
  EXPECT_NEAR(exact->omega_sr,
              4.0 * std::asin(a * b / std::sqrt((a * a + d * d) * (b * b + d * d))), 1e-9);
  EXPECT_LT(exact->omega_sr, formula->omega_sr);
}

}  // namespace
}  // namespace luxgrid::calc::glare
