// calc/nearfield/switch_run.h: the near/far weights of a run of emitters, four pairs' angles as
// lanes, against switch_weights one pair at a time, bit for bit, in both versions the
// multiversioning macro makes: emitters with an error-bound map (turned and not) and without,
// a point opening, points in every direction (the vertical below and above a luminaire, where
// the lanes hand the pair back to switch_weights), at a centroid, near and far; and the lanes'
// photometric angles against photometry::angles_of.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/switch_run.h"
#include "nearfield_test_support.h"
#include "photometry/photometry.h"

namespace luxgrid::nearfield {
namespace {

bool run_same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_weights(const SwitchWeights& a, const SwitchWeights& b) {
  return run_same_bits(a.far, b.far) && run_same_bits(a.fixed, b.fixed) &&
         run_same_bits(a.far_start_m, b.far_start_m) &&
         run_same_bits(a.fixed_start_m, b.fixed_start_m) &&
         run_same_bits(a.distance_m, b.distance_m);
}

TEST(SwitchRun, LaneAnglesAreAnglesOf) {
  // Random unit directions, the axes and directions a rounding away from them: where the lanes
  // say they hold, c and gamma are angles_of's to the bit; they hold for every direction off
  // the vertical (a horizontal part whose square underflows counts as vertical).
  std::mt19937_64 rng(37);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Vec3> dirs = {Vec3(1, 0, 0),       Vec3(-1, 0, 0),    Vec3(0, 1, 0),
                            Vec3(0, -1, 0),      Vec3(0, 0, 1),     Vec3(0, 0, -1),
                            Vec3(1e-300, 0, -1), Vec3(0, -0.0, -1), Vec3(-1, -0.0, 0),
                            Vec3(1, -1e-17, 0)};
  for (int i = 0; i < 4000; ++i) dirs.push_back(glm::normalize(Vec3(n(rng), n(rng), n(rng))));
  while (dirs.size() % simd::kLanes != 0) dirs.push_back(Vec3(0, 0, -1));
  int held = 0, off_vertical = 0, differ = 0;
  for (size_t k = 0; k < dirs.size(); k += simd::kLanes) {
    // (Lambdas that return doubles: one returning lanes would be a call, util/simd.h.)
    const simd::D4 x = simd::make<simd::D4>([&](int l) { return dirs[k + l].x; });
    const simd::D4 y = simd::make<simd::D4>([&](int l) { return dirs[k + l].y; });
    const simd::D4 z = simd::make<simd::D4>([&](int l) { return dirs[k + l].z; });
    simd::D4 c, gamma;
    const simd::L4 ok = photometry::table_angles_of(x, y, z, c, gamma);
    for (int l = 0; l < simd::kLanes; ++l) {
      const Vec3& d = dirs[k + l];
      off_vertical += d.x * d.x + d.y * d.y > 0.0;  // (1e-300 squared underflows)
      if (!ok[l]) continue;
      ++held;
      const photometry::PhotometricAngles a = photometry::angles_of(d);
      differ += !run_same_bits(a.c, c[l]) || !run_same_bits(a.gamma, gamma[l]);
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_EQ(held, off_vertical);
}

using SwitchRunFn = void (*)(const Emitter* const*, size_t, const Vec3&, SwitchWeights*);

void expect_switch_run_same_bits(SwitchRunFn run) {
  const photometry::Photometry ph = photometry::load_photometry_file(
      std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/ldt/zumtobel_mirel_isym4.ldt");
  const Emitter base = make_emitter(ph.opening, Vec3(0, 0, 3), glm::dmat3(1.0), ph.distribution);
  // One map shared by the copies (as a hall's luminaires share theirs): measured once.
  const auto bound = build_far_field_bound(base, Model::standard(), kStandardPromise);
  std::mt19937_64 rng(38);
  std::uniform_real_distribution<double> u(-6.0, 6.0), angle(0.0, 6.283185307179586);
  std::vector<Emitter> emitters;
  for (int k = 0; k < 11; ++k) {
    // Every third one as the base, the others turned about z and tilted about y.
    const double a = angle(rng);
    const glm::dmat3 about_z(std::cos(a), std::sin(a), 0.0, -std::sin(a), std::cos(a), 0.0, 0.0,
                             0.0, 1.0);
    const glm::dmat3 turn =
        k % 3 == 0 ? glm::dmat3(1.0) : testing::rotation_about_y(0.4 * angle(rng)) * about_z;
    Emitter e = make_emitter(ph.opening, Vec3(u(rng), u(rng), 3.0), turn, ph.distribution);
    if (k != 4) e.far_bound = bound;  // one without a map: the five-times rule
    emitters.push_back(e);
  }
  photometry::LuminousOpening point_opening;  // a point: no size, far field everywhere
  emitters.push_back(make_emitter(point_opening, Vec3(1, 2, 3), glm::dmat3(1.0), ph.distribution));
  emitters.back().far_bound = bound;
  std::vector<const Emitter*> batch;
  for (const Emitter& e : emitters) batch.push_back(&e);
  batch.push_back(&emitters[2]);  // one twice: the order counts
  std::vector<Vec3> points;
  for (int i = 0; i < 300; ++i) points.push_back(Vec3(4 * u(rng), 4 * u(rng), 0.5 * u(rng)));
  for (int k : {0, 3, 5}) {
    points.push_back(emitters[k].centroid - Vec3(0, 0, 2.25));  // the vertical below
    points.push_back(emitters[k].centroid + Vec3(0, 0, 1.0));   // and above
    points.push_back(emitters[k].centroid);                     // at the centroid
  }
  int differ = 0, far = 0, near = 0;
  std::vector<SwitchWeights> out(batch.size());
  for (const Vec3& p : points) {
    // Every run length, so each tail is tried.
    for (size_t count : {batch.size(), batch.size() - 1, size_t(3), size_t(0)}) {
      run(batch.data(), count, p, out.data());
      for (size_t k = 0; k < count; ++k) {
        const SwitchWeights one = switch_weights(*batch[k], p);
        differ += !same_weights(out[k], one);
        far += one.far >= 1.0, near += one.far <= 0.0;
      }
    }
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(far, 100);  // both sides of the switch were tried
  EXPECT_GT(near, 100);
}

TEST(SwitchRun, SameBitsAsPairByPairBaseline) {
  expect_switch_run_same_bits(switch_weights_run_default);
}

TEST(SwitchRun, SameBitsAsPairByPairAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "no AVX2 on this processor";
  expect_switch_run_same_bits(switch_weights_run_avx2);
}

}  // namespace
}  // namespace luxgrid::nearfield
