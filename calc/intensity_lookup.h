#pragma once
// Which intensity lookup the far-field pairs and the first bounce use, per distinct distribution
// of a scene: the light distribution texture (photometry/distribution_texture.h: no atan2, an
// addition-and-division lookup of ~11 ns against ~60-80 ns for the table) where a measured bound
// says it is close enough to the table for the quality's promise, else the exact table.
//
// A texture resamples the table's interpolant on a grid that is regular in diamond angles, not
// on the table's own C planes and gamma rows: where the interpolant has a kink (every measured
// angle of a bilinear table, the steep edge of a beam, the end of the data) the texture rounds
// it off over one texel. So the texture is measured against its source before it is used
// (texture_deviation) and kept for a quality only when the bound is within
// kTexturePromiseShare of the quality's promise (calc/plan_estimates.h): 0.1 % at standard,
// 0.03 % at high. Refused, the texel grid is doubled (at most kTextureRaises times, and only
// while doubling can still reach the limit), else the distribution keeps its table. A probe on
// a few texels (sampled_texture_deviation) refuses a texture that is clearly too far off before
// it is built. Reference
// always looks the table up; draft, which promises nothing, always takes the first texture.
// The plan states the choice and the bound per distribution (docs/photometry.md).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "calc/nearfield/emitter.h"
#include "calc/scene.h"
#include "photometry/distribution_texture.h"

namespace luxgrid::calc {

// The first texel grid tried (0.25..0.5 deg per texel) and how often it may be doubled: once,
// to 2880 x 1440 (16.6 MB of floats). On the test corpus the five files within 4 x the 0.1 %
// limit at 1440 x 720 stayed above it at 2880 x 1440 (0.114 % -> 0.10 % for the best: errors
// that do not shrink with the texel, such as a step in the data); a second doubling (66 MB,
// about 25 s of CPU to build and measure) brought one under it.
inline constexpr int kTextureCCells = 1440;
inline constexpr int kTextureGammaCells = 720;
inline constexpr int kTextureRaises = 1;
// A texture costs about 0.15 s to build and measure (1440 x 720, two cores) and saves about 40 ns
// per far-field pair: below this many luminaire-point pairs of one distribution (its copies
// times the scene's points) the table is kept without trying (the office at draft: 12 612 pairs,
// 0.5 ms saved for 150 ms spent).
inline constexpr double kTexturePayoffPairs = 4e6;
// The share of the quality's promise the texture may spend: the rest is the models' own.
inline constexpr double kTexturePromiseShare = 0.1;
// Deviations are relative to max(I, this x the largest intensity): the promise itself exempts
// points darker than 1 % of the surface's maximum, and a relative error where the table is
// (nearly) zero means nothing.
inline constexpr double kTextureDeviationFloor = 0.01;
// The bound is this multiple of the largest deviation sampled at texel centres and edge
// midpoints. A smooth interpolant's bilinear error peaks at those midpoints; a kink of the
// table at a fraction a of a texel gives the texture its largest error a (1 - a) x h x (slope
// jump) at the kink, while the nearest midpoint sees a/2 of it: at most 2 x the sampled value.
inline constexpr double kTextureBoundFactor = 2.0;

struct TextureDeviation {
  double sampled = 0.0;  // largest relative deviation at the texel centres and edge midpoints
  double bound = 0.0;    // kTextureBoundFactor x sampled
};

// |I_texture - I_source| / max(I_source, kTextureDeviationFloor x I_max) at every texel centre
// and every texel edge midpoint (three directions per texel), in parallel over rows; I_max is the
// largest texel (the texels are the source's values at their exact directions).
TextureDeviation texture_deviation(const photometry::DistributionTexture& texture,
                                   const photometry::IntensityDistribution& source);

// The same measure before building a texture c_cells x gamma_cells, on every `stride`-th texel
// in both directions, from the source alone (the bilinear texture's value at a texel's centre is
// the mean of its four corner texels, at an edge's midpoint the mean of the edge's two); I_max is
// the largest corner sampled. A few per cent of the full measurement's cost: a texture that is
// clearly too far off is refused without being built.
TextureDeviation sampled_texture_deviation(const photometry::IntensityDistribution& source,
                                           int c_cells, int gamma_cells, int stride);
// The probe's stride: 1/64 of the texels.
inline constexpr int kTextureProbeStride = 8;

// The relative deviation from the table a texture may have at a quality: infinite at draft, 0
// (never) at reference, kTexturePromiseShare x the promise otherwise.
double texture_limit(Quality quality);

// What a distribution's far-field pairs look up and why, with the numbers the reason quotes
// (report/plan_text.h words it).
struct IntensityLookupChoice {
  enum class Kind {
    analytic,                // an analytic profile: exact, no table to look up
    table_by_quality,        // the quality always looks the table up (reference)
    table_few_pairs,         // too few pairs for a texture to pay for its building
    table_float_range,       // intensities beyond a float texel's range
    table_probe_deviates,    // the probe of texture c x gamma deviates beyond the limit
    texture_draft,           // draft takes the texture without a limit (the probe's deviation)
    texture_within,          // the texture is within the limit (the full measurement)
    table_texture_deviates,  // the texture's full measurement deviates beyond the limit
  };
  Kind kind = Kind::analytic;
  Quality quality = Quality::standard;
  int c_cells = 0, gamma_cells = 0;  // the texture measured
  double deviation = 0.0;            // its measured bound, relative
  double limit = 0.0;                // texture_limit(quality), relative
  int probe_fraction = 0;            // the probe measures 1 / probe_fraction of the texels
  size_t pairs = 0;                  // table_few_pairs: the luminaire-point pairs
};

// Luminaires the plan speaks of together: a photometry entry and how many luminaires share one
// decision (and the label of the first, named when it is the only one).
struct LuminaireGroup {
  std::string photometry;
  size_t luminaires = 0;
  std::string label;
};

// The intensity lookup of one distinct distribution, for the plan.
struct IntensityLookupPlan {
  LuminaireGroup group;
  IntensityLookupChoice choice;
};

struct IntensityLookup {
  // What far-field pairs and the first bounce look intensities up in: the texture or the source.
  photometry::DistributionPtr lookup;
  std::shared_ptr<const photometry::DistributionTexture> texture;  // set when `lookup` is one
  int c_cells = 0, gamma_cells = 0;  // of the last texture measured (0: none built)
  double bound = -1.0;               // its measured bound (-1: none built)
  IntensityLookupChoice choice;      // for the plan
};

// The lookup of one distribution at a quality (see the top of this file). Only a table
// (photometry/tabular_distribution.h) gets a texture; an analytic profile is its own lookup.
IntensityLookup choose_intensity_lookup(const photometry::DistributionPtr& distribution,
                                        Quality quality);

// What one luminaire's distribution looks up: `lookup` (a texture, a texture times the
// luminaire's factor, or the distribution itself) and, when a texture, the texture and factor
// for the hot loops (calc/direct.cpp).
struct LuminaireLookup {
  photometry::DistributionPtr lookup;
  const photometry::DistributionTexture* texture = nullptr;
  double factor = 1.0;
};

// One lookup per distinct distribution among the scene's luminaires, keyed by the distribution
// under its factors (calc/scaled_distribution.h: a multiplier, flux_lm, a TILT factor per
// luminaire), so array members, copies and tilted luminaires of one file share one texture,
// built and measured once; and one plan line for each.
struct SceneLookups {
  std::map<const photometry::IntensityDistribution*, IntensityLookup> by_base;
  std::map<const photometry::IntensityDistribution*, LuminaireLookup> by_distribution;
  std::vector<IntensityLookupPlan> plan;
};
SceneLookups choose_intensity_lookups(const Scene& scene);

// Sets far_distribution, far_texture and far_texture_factor of each emitter.
void attach_intensity_lookups(const SceneLookups& lookups,
                              std::vector<nearfield::Emitter>& emitters);

}  // namespace luxgrid::calc
