#pragma once
// The accuracy-versus-time study (docs/accuracy.md), after the evaluation protocol of
// [Luksch2020, Sec. 6]: a 1 x 1 emitter centred at heights 0.1, 1.0 and 2.5 over a ground plane
// (z = 0, normal +z), turned so that the angle between its emitting normal and the ground normal is
// pi/2, 5/8 pi, 3/4 pi, 7/8 pi or pi, receivers on a regular grid over the 5 x 5 region centred
// under the light. For each data set and height, every model of the near-field ladder is run on
// all points of all five orientations ("stitched", as in the paper's Fig. 10) and compared with
// the converged reference integrator; the time per evaluation is measured on one thread.
//
// Error measure: NRMS = sqrt(mean (E_model - E_ref)^2) / sqrt(mean E_ref^2) over the stitched
// points (the RMS error relative to the RMS illuminance: scale-free, so candela values of the
// files do not matter). "centre" is the signed relative error at the ground point straight below
// the emitter facing down (orientation pi), the number that shows the published cubature's bias
// most plainly (-28 % for a cosine emitter at h = 0.1 with the paper's cubature).
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "calc/nearfield/illuminance.h"
#include "photometry/intensity_distribution.h"

namespace luxgrid::study {

struct AccuracyDataSet {
  std::string name;  // "cosine", "batwing", "zumtobel_arcos3_isym1", ...
  photometry::DistributionPtr distribution;
};

// A model of the study: a rung of the near-field ladder (calc/nearfield) or one of the
// baselines it is measured against (baselines.h).
struct AccuracyModel {
  enum class Kind { ladder, structured_sampling, most_representative_point, monte_carlo };
  std::string
      name;  // nearfield::to_string(ladder) for a rung; "structured sampling", "MRP", "MC N"
  Kind kind = Kind::ladder;
  nearfield::Model ladder;  // kind == ladder
  int samples = 0;          // kind == monte_carlo
  bool is_monte_carlo() const { return kind == Kind::monte_carlo; }

  static AccuracyModel rung(const nearfield::Model& model);
  static AccuracyModel structured_sampling();
  static AccuracyModel most_representative_point();
  static AccuracyModel monte_carlo(int samples);
};

// Illuminance (lx) of `model` at `point` with unit `normal`; `seed` seeds Monte Carlo.
double evaluate(const AccuracyModel& model, const nearfield::Emitter& emitter, const Vec3& point,
                const Vec3& normal, std::uint64_t seed);

struct AccuracyOptions {
  std::vector<double> heights{0.1, 1.0, 2.5};
  int grid = 24;                      // receivers per side over the 5 x 5 region (cell centres)
  double region = 5.0;                // side of the receiver region (units)
  double reference_tolerance = 1e-7;  // relative tolerance of the reference integrator
};

// The paper's orientations: angle between the emitter's normal and the ground normal (rad).
std::vector<double> protocol_orientations();

// Points dimmer than this fraction of their cell's brightest are left out of the per-point
// relative error: 1 % of a value a thousandth of the peak is not a reading anyone uses, and
// behind a one-sided profile the value is 0.
inline constexpr double kPointErrorFloor = 1e-3;

// One (data set, height, model) cell of the study.
struct AccuracyCell {
  std::string data_set;
  double height = 0.0;
  std::string model;
  int model_index = 0;  // index into the study's models
  double nrms = 0.0;
  double max_rel = 0.0;     // largest |E - E_ref| / max(E_ref) over the stitched points
  double point_rel = 0.0;   // largest |E - E_ref| / E_ref over the points with E_ref >=
                            // kPointErrorFloor x max(E_ref) (the promise's "1 % at every point")
  double centre_rel = 0.0;  // signed relative error below the centre, orientation pi
  double ns_per_eval = 0.0;
};

struct AccuracyStudy {
  AccuracyOptions options;
  std::vector<std::string> data_sets;
  std::vector<AccuracyModel> models;
  std::vector<AccuracyCell> cells;            // data set major, then height, then model
  int points_per_cell = 0;                    // receivers x orientations
  double reference_ns_per_eval = 0.0;         // the truth's own cost (mean)
  double reference_max_error_estimate = 0.0;  // largest relative error estimate it reported
  double cosine_vs_lambert_max_rel = -1.0;    // reference vs exact Lambert, cosine data set

  // Mean NRMS and mean ns per evaluation of model `m` over all data sets and heights.
  double mean_nrms(int m) const;
  double mean_ns(int m) const;
  const AccuracyCell& cell(const std::string& data_set, double height, int m) const;
};

// The models of the study: far field, structured sampling, MRP, the paper's cubature,
// subdivided k = 1..3, lambert k = 1..3, adaptive, standard, a looser reference, and Monte Carlo
// with 8 to 4096 samples (quick: fewer Monte Carlo levels).
std::vector<AccuracyModel> accuracy_models(bool quick);

// The data sets: a cosine (Lambertian) emitter, a batwing, then the given LDT/IES files
// (loaded with load_photometry_file; the opening in the file is ignored: the protocol's 1 x 1
// square is used).
std::vector<AccuracyDataSet> accuracy_data_sets(const std::vector<std::filesystem::path>& files);

// The seven Zumtobel data sets of the paper, in `ldt_dir`.
std::vector<std::filesystem::path> paper_ldt_files(const std::filesystem::path& ldt_dir);
// Corpus files of a very different character (spot, asymmetric flood, roadway), found beside
// `ldt_dir` (its parent's ies/ and ldt/ folders); the full study adds them after the paper's.
std::vector<std::filesystem::path> contrast_files(const std::filesystem::path& ldt_dir);

using AccuracyProgress = std::function<void(const std::string& what)>;

AccuracyStudy run_accuracy_study(const std::vector<AccuracyDataSet>& data_sets,
                                 const std::vector<AccuracyModel>& models,
                                 const AccuracyOptions& options,
                                 const AccuracyProgress& progress = {});

// Markdown: the summary per model, then NRMS per data set and height for the cubature, the
// subdivided rungs and Monte Carlo at equal time.
std::string format_accuracy_markdown(const AccuracyStudy& study, const std::string& command);

// Error versus time (log-log), one point per model, the Pareto front drawn through the models
// no other model beats in both. Drawn on a report::Raster and written as PNG; throws
// CalculationError on failure.
void write_accuracy_plot(const AccuracyStudy& study, const std::filesystem::path& png);

// Monte Carlo model whose mean time per evaluation is closest (in log) to `ns`, or -1.
int monte_carlo_at_time(const AccuracyStudy& study, const std::string& data_set, double height,
                        double ns);

}  // namespace luxgrid::study
