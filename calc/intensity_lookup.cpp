#include "calc/intensity_lookup.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <tbb/parallel_for.h>

#include "calc/plan_estimates.h"
#include "calc/scaled_distribution.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::calc {

using photometry::DistributionTexture;

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

TextureDeviation texture_deviation(const DistributionTexture& tex,
                                   const photometry::IntensityDistribution& source) {
  const int nu = tex.c_cells(), nv = tex.gamma_cells();
  const auto direction = [&](double i, double j) {
    return DistributionTexture::direction_of_diamond(4.0 * i / nu, 2.0 * j / nv);
  };
  // I_max from the texels, which are the source's values at their directions.
  std::vector<double> row_max(static_cast<size_t>(nv) + 1, 0.0);
  tbb::parallel_for(0, nv + 1, [&](int j) {
    double m = 0.0;
    for (int i = 0; i < nu; ++i) {
      const double t = tex.intensity(DistributionTexture::texel_direction(i, j, nu, nv));
      m = std::isfinite(t) ? std::max(m, t) : kInfinity;
    }
    row_max[static_cast<size_t>(j)] = m;
  });
  const double max_cd = *std::max_element(row_max.begin(), row_max.end());
  if (!std::isfinite(max_cd)) return {kInfinity, kInfinity};  // beyond a float texel's range
  const double floor_cd = kTextureDeviationFloor * max_cd;
  if (!(floor_cd > 0.0)) return {};  // dark everywhere: nothing to be wrong about
  std::vector<double> row_dev(static_cast<size_t>(nv), 0.0);
  tbb::parallel_for(0, nv, [&](int j) {
    double worst = 0.0;
    for (int i = 0; i < nu; ++i) {
      // The texel's centre, the midpoint of its lower edge (in v) and of its left edge (in u).
      const Vec3 dirs[3] = {direction(i + 0.5, j + 0.5), direction(i + 0.5, j),
                            direction(i, j + 0.5)};
      for (int k = 0; k < 3; ++k) {
        if (k == 1 && j == 0) continue;  // the pole row's midpoints are the pole
        const double exact = source.intensity(dirs[k]);
        worst =
            std::max(worst, std::abs(tex.intensity(dirs[k]) - exact) / std::max(exact, floor_cd));
      }
    }
    row_dev[static_cast<size_t>(j)] = worst;
  });
  const double sampled = *std::max_element(row_dev.begin(), row_dev.end());
  return {sampled, kTextureBoundFactor * sampled};
}

TextureDeviation sampled_texture_deviation(const photometry::IntensityDistribution& source, int nu,
                                           int nv, int stride) {
  const auto direction = [&](double i, double j) {
    return DistributionTexture::direction_of_diamond(4.0 * i / nu, 2.0 * j / nv);
  };
  const auto texel = [&](int i, int j) {
    return static_cast<double>(static_cast<float>(
        source.intensity(DistributionTexture::texel_direction(i % nu, j, nu, nv))));
  };
  const int rows = (nv + stride - 1) / stride;
  struct Row {
    double max_cd = 0.0;
    std::vector<std::pair<double, double>> pairs;  // (texture, source) at the sampled points
  };
  std::vector<Row> per_row(static_cast<size_t>(rows));
  tbb::parallel_for(0, rows, [&](int r) {
    // Offsets that change from row to row (steps 3 and 5, coprime to a power-of-two stride), so
    // the probe does not fall on the same phase of a regular table's angles in every row.
    const int j = std::min(r * stride + (3 * r) % stride, nv - 1);
    Row& row = per_row[static_cast<size_t>(r)];
    for (int i = (5 * r) % stride; i < nu; i += stride) {
      const double t00 = texel(i, j), t10 = texel(i + 1, j), t01 = texel(i, j + 1),
                   t11 = texel(i + 1, j + 1);
      for (double t : {t00, t10, t01, t11})
        row.max_cd = std::isfinite(t) ? std::max(row.max_cd, t) : kInfinity;
      row.pairs.emplace_back(0.25 * (t00 + t10 + t01 + t11),
                             source.intensity(direction(i + 0.5, j + 0.5)));
      if (j > 0) row.pairs.emplace_back(0.5 * (t00 + t10), source.intensity(direction(i + 0.5, j)));
      row.pairs.emplace_back(0.5 * (t00 + t01), source.intensity(direction(i, j + 0.5)));
    }
  });
  double max_cd = 0.0;
  for (const Row& row : per_row) max_cd = std::max(max_cd, row.max_cd);
  if (!std::isfinite(max_cd)) return {kInfinity, kInfinity};  // beyond a float texel's range
  const double floor_cd = kTextureDeviationFloor * max_cd;
  if (!(floor_cd > 0.0)) return {};
  double sampled = 0.0;
  for (const Row& row : per_row)
    for (const auto& [tex, exact] : row.pairs)
      sampled = std::max(sampled, std::abs(tex - exact) / std::max(exact, floor_cd));
  return {sampled, kTextureBoundFactor * sampled};
}

double texture_limit(Quality quality) {
  switch (quality) {
    case Quality::draft: return std::numeric_limits<double>::infinity();
    case Quality::reference: return 0.0;
    case Quality::standard:
    case Quality::high: break;
  }
  return kTexturePromiseShare * promised_error(quality);
}

namespace {
// The texture of `source`, its texels sampled in parallel over rows.
std::shared_ptr<const DistributionTexture> build_texture(
    const photometry::IntensityDistribution& source, int nu, int nv) {
  std::vector<float> texels(static_cast<size_t>(nu) * static_cast<size_t>(nv + 1));
  tbb::parallel_for(0, nv + 1, [&](int j) {
    for (int i = 0; i < nu; ++i)
      texels[static_cast<size_t>(j) * static_cast<size_t>(nu) + static_cast<size_t>(i)] =
          static_cast<float>(source.intensity(DistributionTexture::texel_direction(i, j, nu, nv)));
  });
  return std::make_shared<const DistributionTexture>(nu, nv, std::move(texels));
}
}  // namespace

IntensityLookup choose_intensity_lookup(const photometry::DistributionPtr& distribution,
                                        Quality quality) {
  using Kind = IntensityLookupChoice::Kind;
  IntensityLookup out;
  out.lookup = distribution;
  out.choice.quality = quality;
  if (!dynamic_cast<const photometry::TabularDistribution*>(distribution.get())) {
    // An analytic profile (isotropic, Lambertian, ...) is exact and cheap as it is: the texture
    // exists to spare a table's two atan2, and would only add its float rounding.
    out.choice.kind = Kind::analytic;
    return out;
  }
  const double limit = texture_limit(quality);
  out.choice.limit = limit;
  out.choice.probe_fraction = kTextureProbeStride * kTextureProbeStride;
  if (!(limit > 0.0)) {
    out.choice.kind = Kind::table_by_quality;
    return out;
  }
  int nu = kTextureCCells, nv = kTextureGammaCells;
  for (int raise = 0;; ++raise) {
    out.choice.c_cells = nu, out.choice.gamma_cells = nv;
    // Doubling the grid divides a smooth interpolant's error by 4 and a kink's by 2: a texture
    // whose probe (a subset of the measurement's directions, its floor from the texels it
    // reads) is beyond 4 x the limit is refused unbuilt,
    // and no finer one is tried; the finest one is refused unbuilt beyond the limit itself.
    const bool last = raise == kTextureRaises;
    const TextureDeviation probe =
        sampled_texture_deviation(*distribution, nu, nv, kTextureProbeStride);
    out.c_cells = nu, out.gamma_cells = nv, out.bound = probe.bound;
    out.choice.deviation = probe.bound;
    if (!std::isfinite(probe.bound)) {
      // Texels are floats (4 bytes, so the texture stays in the caches): intensities beyond
      // 3.4e38 cd would be infinite there. No quality takes that, draft included.
      out.choice.kind = Kind::table_float_range;
      return out;
    }
    if (probe.bound > (last ? 1.0 : 4.0) * limit) {
      out.choice.kind = Kind::table_probe_deviates;
      return out;
    }
    auto tex = build_texture(*distribution, nu, nv);
    if (quality == Quality::draft) {
      // Draft takes the texture without a limit: the probe says how close it is.
      out.lookup = tex;
      out.texture = std::move(tex);
      out.choice.kind = Kind::texture_draft;
      return out;
    }
    const TextureDeviation dev = texture_deviation(*tex, *distribution);
    out.bound = dev.bound;
    out.choice.deviation = dev.bound;
    if (dev.bound <= limit) {
      out.lookup = tex;
      out.texture = std::move(tex);
      out.choice.kind = Kind::texture_within;
      return out;
    }
    if (last || dev.bound > 4.0 * limit) {
      out.choice.kind = Kind::table_texture_deviates;
      return out;
    }
    nu *= 2, nv *= 2;
  }
}

namespace {
// The distribution under its constant factors, and their product.
photometry::DistributionPtr base_of(photometry::DistributionPtr d, double& factor) {
  factor = 1.0;
  while (const auto* scaled = dynamic_cast<const ScaledDistribution*>(d.get())) {
    factor *= scaled->factor();
    d = scaled->inner();
  }
  return d;
}
}  // namespace

SceneLookups choose_intensity_lookups(const Scene& scene) {
  SceneLookups out;
  struct Distinct {
    const photometry::IntensityDistribution* base;
    std::string photometry;
    size_t first = 0, members = 0;
  };
  std::vector<Distinct> distinct;
  // Luminaire-point pairs each distinct distribution will light: a texture pays for its
  // building only beyond kTexturePayoffPairs of them.
  size_t points = 0;
  for (const auto& g : scene.surfaces) points += g.points.size();
  std::map<const photometry::IntensityDistribution*, size_t> copies;
  for (const Luminaire& lum : scene.luminaires) {
    double factor = 1.0;
    ++copies[base_of(lum.distribution, factor).get()];
  }
  for (size_t i = 0; i < scene.luminaires.size(); ++i) {
    const Luminaire& lum = scene.luminaires[i];
    double factor = 1.0;
    const photometry::DistributionPtr base = base_of(lum.distribution, factor);
    auto [it, fresh] = out.by_base.try_emplace(base.get());
    if (fresh) {
      const double pairs = static_cast<double>(copies[base.get()]) * static_cast<double>(points);
      if (pairs < kTexturePayoffPairs && scene.settings.quality != Quality::reference &&
          dynamic_cast<const photometry::TabularDistribution*>(base.get())) {
        it->second.lookup = base;
        it->second.choice.kind = IntensityLookupChoice::Kind::table_few_pairs;
        it->second.choice.quality = scene.settings.quality;
        it->second.choice.pairs = static_cast<size_t>(pairs);
      } else {
        it->second = choose_intensity_lookup(base, scene.settings.quality);
      }
      distinct.push_back({base.get(), lum.photometry, i, 0});
    }
    ++std::find_if(distinct.begin(), distinct.end(), [&](const Distinct& d) {
        return d.base == base.get();
      })->members;
    auto [mine, new_distribution] = out.by_distribution.try_emplace(lum.distribution.get());
    if (!new_distribution) continue;
    const IntensityLookup& chosen = it->second;
    if (!chosen.texture) {
      mine->second = {lum.distribution, nullptr, 1.0};
    } else if (lum.distribution.get() == base.get()) {
      mine->second = {chosen.texture, chosen.texture.get(), 1.0};
    } else {
      mine->second = {std::make_shared<ScaledDistribution>(chosen.texture, factor),
                      chosen.texture.get(), factor};
    }
  }
  for (const Distinct& d : distinct)
    out.plan.push_back({{d.photometry, d.members, scene.luminaires[d.first].label},
                        out.by_base.at(d.base).choice});
  return out;
}

void attach_intensity_lookups(const SceneLookups& lookups,
                              std::vector<nearfield::Emitter>& emitters) {
  for (nearfield::Emitter& e : emitters) {
    const auto it = lookups.by_distribution.find(e.distribution.get());
    if (it == lookups.by_distribution.end()) continue;
    e.far_distribution = it->second.lookup;
    e.far_texture = it->second.texture;
    e.far_texture_factor = it->second.factor;
  }
}

}  // namespace luxgrid::calc
