// Interpolation invariants of TabularDistribution and DistributionTexture:
// exact at measured angles, continuous across C = 0/360 and at the poles, symmetric files give
// symmetric lookups, bicubic never negative, flux of a constant table is 4 pi I to 1e-9, flux of
// I0 cos(gamma) on the lower hemisphere is pi I0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "photometry/builtin.h"
#include "photometry/derived_photometry.h"
#include "photometry/distribution_texture.h"
#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::photometry {
namespace {

std::vector<std::filesystem::path> corpus() {
  std::vector<std::filesystem::path> out;
  for (const char* sub : {"ies", "ldt"})
    for (const auto& e : std::filesystem::directory_iterator(
             std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry" / sub))
      out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

double max_cd(const TabularDistribution& t) {
  return *std::max_element(t.grid().cd.begin(), t.grid().cd.end());
}

const Interpolation kModes[] = {Interpolation::bilinear, Interpolation::bicubic};

TEST(Interpolation, CorpusHas66Files) { EXPECT_EQ(corpus().size(), 66u); }

TEST(Interpolation, ExactAtMeasuredAngles) {
  for (const auto& f : corpus()) {
    const Photometry p = load_photometry_file(f);
    for (Interpolation mode : kModes) {
      const auto t = p.table->with_interpolation(mode);
      const SphericalGrid& g = t->grid();
      const double scale = std::max(1.0, max_cd(*t));
      for (std::size_t i = 0; i < g.c_rad.size(); ++i)
        for (std::size_t j = 0; j < g.gamma_rad.size(); ++j) {
          // By angles: the very value; by direction: through atan2, so to rounding.
          ASSERT_NEAR(t->intensity_at(g.c_rad[i], g.gamma_rad[j]), g.at(i, j), 1e-12 * scale)
              << f.filename() << " " << to_string(mode) << " C " << g.c_rad[i] * kRadToDeg
              << " gamma " << g.gamma_rad[j] * kRadToDeg;
          // A pole is one direction: only a pole-averaged grid can be exact there by direction
          // (type B/A grids with data over half a turn keep each plane's pole value).
          const bool pole = g.gamma_rad[j] < 1e-12 || g.gamma_rad[j] > kPi - 1e-12;
          if (pole && !g.average_poles) continue;
          const Vec3 d = t->luminaire_direction(g.c_rad[i], g.gamma_rad[j]);
          ASSERT_NEAR(t->intensity(d), g.at(i, j), 1e-7 * scale) << f.filename();
        }
    }
  }
}

TEST(Interpolation, ExactAtTheFilesOwnNumbers) {
  // lithonia_esg: multiplier 1; plane C0 starts 166 160 125 (gamma 0, 2.5, 5); plane C22.5 at
  // gamma 2.5 is 158; the quadrant mirror puts the C22.5 plane at C157.5, C202.5 and C337.5.
  const Photometry p =
      load_photometry_file(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                           "tests/data/photometry/ies/lithonia_esg_iesna91_commas.ies");
  for (Interpolation mode : kModes) {
    const auto t = p.table->with_interpolation(mode);
    EXPECT_DOUBLE_EQ(t->intensity_at(0, 0), 166);
    EXPECT_NEAR(t->intensity(direction_of(0, 5 * kDegToRad)), 125, 1e-9);
    for (double c : {22.5, 157.5, 202.5, 337.5})
      EXPECT_NEAR(t->intensity(direction_of(c * kDegToRad, 2.5 * kDegToRad)), 158, 1e-9) << c;
    EXPECT_EQ(t->intensity(direction_of(0, 91 * kDegToRad)), 0.0);  // file stops at 90
  }
}

TEST(Interpolation, ContinuousAcrossC0AndAtThePoles) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> gamma(0.0, kPi);
  for (const auto& f : corpus()) {
    const Photometry p = load_photometry_file(f);
    for (Interpolation mode : kModes) {
      const auto t = p.table->with_interpolation(mode);
      const double scale = std::max(1.0, max_cd(*t));
      // Across C = 0/360 in the luminaire frame (directions y = +-eps, x > 0).
      for (int k = 0; k < 50; ++k) {
        const double g = gamma(rng);
        const Vec3 a = glm::normalize(Vec3(std::sin(g), 1e-10, -std::cos(g)));
        const Vec3 b = glm::normalize(Vec3(std::sin(g), -1e-10, -std::cos(g)));
        ASSERT_NEAR(t->intensity(a), t->intensity(b), 1e-6 * scale)
            << f.filename() << " gamma " << g;
      }
      // Towards each pole from every side.
      for (double z : {-1.0, 1.0}) {
        const double at_pole = t->intensity({0, 0, z});
        for (int k = 0; k < 36; ++k) {
          const double c = k * 10 * kDegToRad;
          const Vec3 near = glm::normalize(Vec3(1e-9 * std::cos(c), 1e-9 * std::sin(c), z));
          ASSERT_NEAR(t->intensity(near), at_pole, 1e-6 * scale) << f.filename() << " z " << z;
        }
      }
    }
  }
}

TEST(Interpolation, SymmetricFilesGiveSymmetricLookups) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const auto& f : corpus()) {
    const Photometry p = load_photometry_file(f);
    if (p.photometric_type != PhotometricType::C) continue;
    for (Interpolation mode : kModes) {
      const auto t = p.table->with_interpolation(mode);
      const double scale = std::max(1.0, max_cd(*t));
      for (int k = 0; k < 200; ++k) {
        const double c = u(rng) * 2 * kPi, g = u(rng) * kPi;
        const double v = t->intensity_at(c, g);
        auto at = [&](double cc) { return t->intensity(direction_of(cc, g)); };
        const double tol = 1e-7 * scale;
        switch (p.symmetry) {
          case Symmetry::rotational: ASSERT_NEAR(at(c + 1.234), v, tol) << f.filename(); break;
          case Symmetry::quadrant:
            ASSERT_NEAR(at(kPi - c), v, tol) << f.filename();
            ASSERT_NEAR(at(kPi + c), v, tol) << f.filename();
            ASSERT_NEAR(at(2 * kPi - c), v, tol) << f.filename();
            break;
          case Symmetry::bilateral_c0_c180:
            ASSERT_NEAR(at(2 * kPi - c), v, tol) << f.filename();
            break;
          case Symmetry::bilateral_c90_c270:
            ASSERT_NEAR(at(kPi - c), v, tol) << f.filename();
            break;
          case Symmetry::none: break;
        }
      }
    }
  }
}

TEST(Interpolation, BicubicIsNeverNegative) {
  // A spike on zeros makes Catmull-Rom undershoot; the lookup must clamp.
  SphericalGrid g;
  g.c_rad = {0, kPi / 2, kPi, 3 * kPi / 2};
  for (int j = 0; j <= 18; ++j) g.gamma_rad.push_back(j * 10 * kDegToRad);
  g.cd.assign(g.c_rad.size() * g.gamma_rad.size(), 0.0);
  g.cd[0 * 19 + 3] = 1000.0;
  g.cd[1 * 19 + 4] = 1000.0;
  const TabularDistribution t(g, Interpolation::bicubic);
  std::mt19937 rng(1);
  std::normal_distribution<double> n;
  double min_seen = 1e300;
  for (int k = 0; k < 100000; ++k) {
    const Vec3 d = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    const double v = t.intensity(d);
    ASSERT_GE(v, 0.0);
    ASSERT_TRUE(std::isfinite(v));
    min_seen = std::min(min_seen, v);
  }
  EXPECT_EQ(min_seen, 0.0);  // the clamp was active somewhere
  for (const auto& f : corpus()) {
    const auto tc = load_photometry_file(f).table->with_interpolation(Interpolation::bicubic);
    for (int k = 0; k < 2000; ++k) {
      const Vec3 d = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
      const double v = tc->intensity(d);
      ASSERT_TRUE(std::isfinite(v) && v >= 0.0) << f.filename();
    }
  }
}

SphericalGrid constant_grid(double i0, std::vector<double> c_deg, std::vector<double> g_deg) {
  SphericalGrid g;
  for (double c : c_deg) g.c_rad.push_back(c * kDegToRad);
  for (double x : g_deg) g.gamma_rad.push_back(x * kDegToRad);
  g.cd.assign(g.c_rad.size() * g.gamma_rad.size(), i0);
  return g;
}

TEST(Flux, ConstantTableIsFourPiI) {
  const double i0 = 123.456;
  const std::vector<SphericalGrid> grids = {
      constant_grid(i0, {0}, {0, 180}),                                   // two rows, one plane
      constant_grid(i0, {0, 90, 180, 270}, {0, 5, 10, 45, 90, 91, 180}),  // irregular
      constant_grid(i0, {0, 7, 100, 200, 359}, {0, 30, 60, 90, 120, 150, 180})};
  for (const auto& g : grids)
    for (Interpolation mode : kModes) {
      const TabularDistribution t(g, mode);
      const FluxResult f = integrate_flux(t);
      EXPECT_NEAR(f.total_lm, 4 * kPi * i0, 1e-9 * 4 * kPi * i0) << to_string(mode);
      EXPECT_NEAR(f.downward_lm, 2 * kPi * i0, 1e-9 * 2 * kPi * i0) << to_string(mode);
    }
}

TEST(Flux, CosineOnTheLowerHemisphereIsPiI0) {
  // I0 cos(gamma) tabulated every 0.5 deg: bilinear misses the curvature by ~h^2/12 (~2e-5);
  // Catmull-Rom is fourth order (~1e-9). The builtin Lambertian is integrated by derive()'s
  // midpoint rule for non-tabular distributions (~1e-5).
  const double i0 = 1000.0;
  SphericalGrid g;
  g.c_rad = {0.0};
  for (int j = 0; j <= 180; ++j) {
    g.gamma_rad.push_back(j * 0.5 * kDegToRad);
    g.cd.push_back(i0 * std::cos(g.gamma_rad.back()));
  }
  g.cd.back() = 0.0;
  const double exact = kPi * i0;
  EXPECT_NEAR(integrate_flux(TabularDistribution(g, Interpolation::bilinear)).total_lm, exact,
              3e-5 * exact);
  EXPECT_NEAR(integrate_flux(TabularDistribution(g, Interpolation::bicubic)).total_lm, exact,
              1e-8 * exact);
  Photometry lambert;
  lambert.distribution = std::make_shared<LambertianDistribution>(i0);
  const DerivedPhotometry d = derive(lambert);
  EXPECT_NEAR(d.flux_lm, exact, 2e-5 * exact);
  EXPECT_NEAR(d.dff, 1.0, 1e-12);
}

TEST(Flux, IsotropicTwoPlaneFileIsFourPi) {
  // MANIFEST: opple_mtd is 1 cd everywhere in two planes {0, 90}: 4 pi lm exactly.
  const Photometry p =
      load_photometry_file(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                           "tests/data/photometry/ies/opple_mtd0700312_lm02_h0_90.ies");
  for (Interpolation mode : kModes)
    EXPECT_NEAR(integrate_flux(*p.table->with_interpolation(mode)).total_lm, 4 * kPi,
                1e-9 * 4 * kPi);
}

TEST(TypeB, MapsIntoTheLuminaireFrame) {
  // mdl_test: V {-90, 90} x H {-90, -45, 0, 45, 90}; values 0.1 .. 1.0 in H-major order.
  // Frame (symmetry.h): aim A = -z, up U = +x (V > 0), lateral L = -y (H > 0).
  const Photometry p = load_photometry_file(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                                            "tests/data/photometry/ies/mdl_test_iesna91_typeb.ies");
  const auto& t = *p.distribution;
  const double s = std::sqrt(0.5);
  EXPECT_NEAR(t.intensity({1, 0, 0}), 0.6, 1e-12);    // H 0, V 90
  EXPECT_NEAR(t.intensity({-1, 0, 0}), 0.5, 1e-12);   // H 0, V -90
  EXPECT_NEAR(t.intensity({s, -s, 0}), 0.8, 1e-12);   // H 45, V 90
  EXPECT_NEAR(t.intensity({-s, s, 0}), 0.3, 1e-12);   // H -45, V -90
  EXPECT_NEAR(t.intensity({0, -1, 0}), 0.95, 1e-12);  // H 90 is one direction: the mean
  EXPECT_NEAR(t.intensity({0, 0, -1}), 0.55, 1e-12);  // the aim, halfway between V = -+90
  EXPECT_NEAR(t.intensity({0, 0, 1}), 0.0, 1e-12);    // behind the floodlight: no data
  EXPECT_EQ(p.photometric_type, PhotometricType::B);
}

TEST(Texture, AgreesWithTheTableAndIsContinuous) {
  for (const char* rel : {"ldt/zumtobel_mirel_isym4.ldt", "ies/deliver_indoor_full360_lm02.ies",
                          "ldt/sample18_mc360_large.ldt"}) {
    const Photometry p = load_photometry_file(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                                              "tests/data/photometry" / rel);
    const double scale = max_cd(*p.table);
    for (Interpolation mode : kModes) {
      const DistributionTexture tex(*p.table, 1440, 720, mode);
      std::mt19937 rng(3);
      std::normal_distribution<double> n;
      double sum_err = 0.0;
      const int samples = 20000;
      for (int k = 0; k < samples; ++k) {
        const Vec3 d = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
        const double v = tex.intensity(d);
        ASSERT_TRUE(std::isfinite(v) && v >= 0.0);
        sum_err += std::abs(v - p.table->intensity(d));
      }
      // A 0.25..0.5 deg texel against 2.5..15 deg data: mean error well below 1 % of the peak
      // (the step to zero at the end of the data is smeared over one texel).
      EXPECT_LT(sum_err / samples, 0.005 * scale) << rel << " " << to_string(mode);
      for (double z : {-1.0, 1.0})
        EXPECT_NEAR(tex.intensity(glm::normalize(Vec3(1e-9, 1e-9, z))), tex.intensity({0, 0, z}),
                    1e-6 * scale);
      EXPECT_NEAR(tex.intensity(glm::normalize(Vec3(1, 1e-12, -1))),
                  tex.intensity(glm::normalize(Vec3(1, -1e-12, -1))), 1e-6 * scale);
    }
  }
  // Diamond angles round-trip.
  for (double u = 0; u < 4; u += 0.173)
    for (double v = 0.01; v < 2; v += 0.123) {
      double u2, v2;
      DistributionTexture::diamond_angles(DistributionTexture::direction_of_diamond(u, v), u2, v2);
      EXPECT_NEAR(u2, u, 1e-12);
      EXPECT_NEAR(v2, v, 1e-12);
    }
  // A constant distribution is reproduced exactly.
  const DistributionTexture iso(IsotropicDistribution(7.0), 64, 32, Interpolation::bicubic);
  EXPECT_NEAR(iso.intensity(glm::normalize(Vec3(0.3, -0.2, 0.5))), 7.0, 1e-6);
}

// The far-field loop looks a run of directions up at once (bilinear_batch, vectorised); its
// values must be bilinear()'s to the last bit, so that a run's sums do not depend on the path.
// Each version of the batch (util/simd.h's LUXGRID_MULTIVERSION) is called by name.
using Batch = void (*)(const float*, int, int, const double*, const double*, const double*, int,
                       double*);
void expect_batch_same_bits_as_one_by_one(Batch batch_lookup) {
  const Photometry p = load_photometry_file(std::filesystem::path(LUXGRID_SOURCE_DIR) /
                                            "tests/data/photometry/ldt/zumtobel_mirel_isym4.ldt");
  const DistributionTexture tex(*p.table, 1440, 720, Interpolation::bilinear);
  std::vector<Vec3> d;
  std::mt19937 rng(5);
  std::normal_distribution<double> n;
  // Unnormalised directions (the loop passes them so), the poles, the axes and the quadrant
  // boundaries (signed zeros), a zero vector and lengths near the underflow.
  for (int k = 0; k < 1000; ++k) d.push_back(Vec3(n(rng), n(rng), n(rng)) * (0.1 + k % 7));
  for (double z : {-1.0, 0.0, 1.0, -0.0})
    for (double x : {-1.0, -0.0, 0.0, 1.0})
      for (double y : {-1.0, -0.0, 0.0, 1.0}) d.push_back(Vec3(x, y, z));
  d.push_back(Vec3(1e-300, -1e-300, 1e-310));
  d.push_back(Vec3(1e-170, 1e-170, -1.0));
  std::vector<double> x, y, z;
  for (const Vec3& v : d) x.push_back(v.x), y.push_back(v.y), z.push_back(v.z);
  std::vector<double> batch(d.size());
  batch_lookup(tex.texels().data(), tex.c_cells(), tex.gamma_cells(), x.data(), y.data(), z.data(),
               static_cast<int>(d.size()), batch.data());
  for (size_t k = 0; k < d.size(); ++k) {
    const double one = tex.bilinear(d[k]);
    EXPECT_EQ(std::memcmp(&one, &batch[k], sizeof one), 0)
        << k << ": " << one << " against " << batch[k];
  }
}

TEST(Texture, BatchLookupGivesTheSameBitsAsOneByOneAvx2) {
  if (!simd::cpu_has_avx2()) GTEST_SKIP() << "this processor has no AVX2";
  expect_batch_same_bits_as_one_by_one(bilinear_batch_texels_avx2);
}
TEST(Texture, BatchLookupGivesTheSameBitsAsOneByOneDefault) {
  expect_batch_same_bits_as_one_by_one(bilinear_batch_texels_default);
}

}  // namespace
}  // namespace luxgrid::photometry
