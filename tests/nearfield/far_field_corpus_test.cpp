// The near/far decision over the whole photometric test corpus (docs/nearfield.md, "What the map
// bounds and what it measures"): wherever the map lets the far field in (far weight > 0), the
// point model is within the quality's promise of the converged area-form reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/illuminance.h"
#include "calc/nearfield/models.h"
#include "photometry/photometry.h"

namespace luxgrid::nearfield {
namespace {

std::vector<std::string> corpus_files() {
  std::vector<std::string> files;
  const std::filesystem::path root =
      std::filesystem::path(LUXGRID_SOURCE_DIR) / "tests/data/photometry";
  for (const char* sub : {"ies", "ldt"})
    for (const auto& entry : std::filesystem::directory_iterator(root / sub))
      if (entry.is_regular_file()) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// A receiver normal facing the opening, turned by up to 75 degrees (the map's receivers,
// far_field_bound.cpp) towards a random side.
Vec3 tilted_normal(const Vec3& u, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Vec3 side = glm::cross(u, std::abs(u.z) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0));
  side = glm::normalize(side);
  const Vec3 side2 = glm::cross(u, side);
  const double azimuth = kTwoPi * uni(rng), tilt = 75.0 * kDegToRad * uni(rng);
  const Vec3 s = std::cos(azimuth) * side + std::sin(azimuth) * side2;
  return -u * std::cos(tilt) + s * std::sin(tilt);
}

struct Outcome {
  long pairs = 0;
  double worst_ratio = 0.0;  // error / promise
  std::string worst_where;
};

// For one file and one quality: random directions, a map built for them, and the pairs where the
// map lets the far field in: just past each direction's far-field distance (where its error is
// largest) and further out (log-uniform to 8 times it).
void check_file(const std::string& path, const Model& model, double promise, std::uint64_t seed,
                int directions, Outcome& out) {
  const photometry::Photometry ph = photometry::load_photometry_file(path);
  // Placed and turned arbitrarily: the map lives in the luminaire frame.
  const glm::dmat3 rot(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(Vec3(1.0, 2.0, 3.0))));
  const Emitter e = make_emitter(ph.opening, Vec3(1.0, -2.0, 3.0), rot, ph.distribution);
  if (e.is_point()) return;  // the far field is the model: nothing to decide
  const double D = e.largest_dimension_m;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<Vec3> dirs;
  MapDemand demand;
  for (int k = 0; k < directions; ++k) {
    const Vec3 u = glm::normalize(Vec3(gauss(rng), gauss(rng), gauss(rng)));
    dirs.push_back(u);
    demand.add(u, 1e3);  // every distance: the map measures each direction to its end
  }
  const auto bound = build_far_field_bound(e, model, promise, &demand);
  // The floor of the promise (far_field_bound.h kDimFloor): the table's peak over the map's
  // directions, as the map takes it.
  double peak = 0.0;
  for (int g = 0; g < kGammaSamples; ++g)
    for (int c = 0; c < kCSamples; ++c)
      peak = std::max(peak, e.distribution->intensity(photometry::direction_of(
                                c * kTwoPi / kCSamples, g * kPi / (kGammaSamples - 1))));
  for (const Vec3& u : dirs) {
    const double start = bound->distance_over_D(u);
    if (!(start < 1e5)) continue;
    for (double s : {start * (1.0 + 0.02 * uni(rng)), start * std::exp(std::log(8.0) * uni(rng))}) {
      const double d = s * D;
      const Vec3 p = e.centroid + d * (e.rotation * u);
      const Vec3 n = e.rotation * tilted_normal(u, rng);
      if (!(bound->weights(u, d).far > 0.0)) continue;
      const double far = far_field_illuminance(e, p, n);
      const ReferenceResult ref = reference_illuminance(e, p, n, 1e-6, 400'000);
      const double floor_lx = kDimFloor * peak / (d * d);
      const double error =
          std::abs(far - ref.illuminance_lx) / std::max(ref.illuminance_lx, floor_lx);
      ++out.pairs;
      if (error / promise > out.worst_ratio) {
        out.worst_ratio = error / promise;
        const photometry::PhotometricAngles a = photometry::angles_of(u);
        char where[256];
        std::snprintf(where, sizeof where, "%s C %.2f gamma %.2f at %.1f D: far %.6g near %.6g",
                      std::filesystem::path(path).filename().c_str(), a.c * kRadToDeg,
                      a.gamma * kRadToDeg, s, far, ref.illuminance_lx);
        out.worst_where = where;
      }
      EXPECT_LE(error, promise) << std::filesystem::path(path).filename() << " u " << u.x << " "
                                << u.y << " " << u.z << " at " << s << " D: far " << far << " near "
                                << ref.illuminance_lx;
    }
  }
}

void check_corpus(const Model& model, double promise, const char* name) {
  Outcome out;
  std::uint64_t seed = 37;
  int files = 0;
  for (const std::string& f : corpus_files()) {
    if (f.size() < 4 || f.compare(f.size() - 3, 3, ".md") == 0) continue;
    try {
      check_file(f, model, promise, seed++, 160, out);
      ++files;
    } catch (const std::exception&) {
      // A file the reader refuses (the corpus holds hostile ones too) has nothing to decide.
    }
  }
  std::printf(
      "%s: %d files, %ld pairs where the far field is chosen, worst error / promise %.3f (%s)\n",
      name, files, out.pairs, out.worst_ratio, out.worst_where.c_str());
  EXPECT_GT(out.pairs, 1000);
}

TEST(FarFieldCorpus, StandardKeepsItsPromiseWhereverTheFarFieldIsChosen) {
  check_corpus(Model::standard(), kStandardPromise, "standard");
}

TEST(FarFieldCorpus, HighKeepsItsPromiseWhereverTheFarFieldIsChosen) {
  check_corpus(Model::high(), kHighPromise, "high");
}

}  // namespace
}  // namespace luxgrid::nearfield
