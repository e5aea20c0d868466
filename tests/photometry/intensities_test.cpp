// IntensityDistribution::intensities looks a run of directions up at once (TabularDistribution:
// the angles as lanes), and quality reference's cubature looks its nodes up through it
// (calc/nearfield/area_reference.cpp): each value must be intensity()'s to the bit. Checked on
// every table of the test corpus (tests/data/photometry: type A, B and C, every symmetry), both
// interpolations, over random unit directions, directions near the poles and on the table's own
// C planes and gamma rows, in runs of every length from 1 to 29 (the lanes and the remainder).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::photometry {
namespace {

struct Lcg {
  uint64_t state = 977;
  double operator()() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  }
};

std::vector<Vec3> directions(Lcg& rng) {
  std::vector<Vec3> out;
  for (int k = 0; k < 600; ++k) {  // uniform on the sphere
    const double z = 2.0 * rng() - 1.0, phi = 2.0 * kPi * rng();
    const double h = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.emplace_back(h * std::cos(phi), h * std::sin(phi), z);
  }
  for (const double g_deg : {0.0, 1e-7, 0.5, 5.0, 45.0, 90.0, 135.0, 179.5, 180.0 - 1e-7, 180.0})
    for (const double c_deg : {0.0, 1e-9, 15.0, 90.0, 180.0, 270.0, 359.9999999}) {
      const double g = g_deg * kPi / 180.0, c = c_deg * kPi / 180.0;
      // gamma from nadir (-z), C from +x towards +y (photometry's frame)
      out.emplace_back(std::sin(g) * std::cos(c), std::sin(g) * std::sin(c), -std::cos(g));
    }
  return out;
}

TEST(Intensities, EqualIntensityBitForBitOnEveryCorpusTable) {
  Lcg rng;
  const std::vector<Vec3> d = directions(rng);
  size_t files = 0, compared = 0;
  for (const char* folder : {"ies", "ldt"})
    for (const auto& entry : std::filesystem::directory_iterator(
             std::string(LUXGRID_SOURCE_DIR) + "/tests/data/photometry/" + folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".ies" && ext != ".ldt" && ext != ".IES" && ext != ".LDT") continue;
      Photometry p;
      try {
        p = load_photometry_file(entry.path().string());
      } catch (const std::exception&) {
        continue;  // the corpus's deliberately broken files
      }
      ++files;
      std::vector<DistributionPtr> tables = {p.distribution};
      if (p.table)
        for (const Interpolation mode : {Interpolation::bilinear, Interpolation::bicubic})
          tables.push_back(p.table->with_interpolation(mode));
      for (const DistributionPtr& t : tables) {
        for (size_t begin = 0, run = 1; begin < d.size(); begin += run, run = run % 29 + 1) {
          const size_t n = std::min(run, d.size() - begin);
          std::vector<double> x(n), y(n), z(n), out(n);
          for (size_t k = 0; k < n; ++k)
            x[k] = d[begin + k].x, y[k] = d[begin + k].y, z[k] = d[begin + k].z;
          t->intensities(x.data(), y.data(), z.data(), n, out.data());
          for (size_t k = 0; k < n; ++k) {
            ASSERT_EQ(out[k], t->intensity(d[begin + k]))
                << entry.path().filename() << " direction " << begin + k;
            ++compared;
          }
        }
      }
    }
  EXPECT_GT(files, 40u);
  EXPECT_GT(compared, 50000u);
}

}  // namespace
}  // namespace luxgrid::photometry
