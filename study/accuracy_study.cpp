#include "study/accuracy_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <sstream>

#include "calc/nearfield/analytic_profiles.h"
#include "calc/nearfield/models.h"
#include "calc/scene.h"
#include "photometry/builtin.h"
#include "photometry/photometry.h"
#include "report/png_file.h"
#include "report/raster.h"
#include "report/raster_text.h"
#include "study/baselines.h"
#include "util/error.h"
#include "util/format.h"

namespace luxgrid::study {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kEmitterSide = 1.0;     // the protocol's 1 x 1 emitter (units = metres here)
constexpr double kIntensityCd = 1000.0;  // of the analytic data sets (NRMS is scale-free)
// Smallest NRMS the plot shows: the reference row is ~1e-6 and would squash the axis.
constexpr double kPlotNrmsFloor = 1e-6;

// Ground receivers: cell centres of a grid x grid raster over the region centred under the light.
std::vector<Vec3> receivers(const AccuracyOptions& o) {
  std::vector<Vec3> pts;
  const double step = o.region / o.grid;
  for (int j = 0; j < o.grid; ++j)
    for (int i = 0; i < o.grid; ++i)
      pts.emplace_back(-0.5 * o.region + (i + 0.5) * step, -0.5 * o.region + (j + 0.5) * step, 0.0);
  return pts;
}

// The emitter for one height and orientation. Facing down is orientation pi; turning it about
// the x axis by (pi - angle) tilts its normal (0, 0, -1) to (0, sin, -cos), whose angle with the
// ground normal +z is `angle`. The centre stays at height h; the part of a tilted emitter below
// the ground is removed by every model's horizon clip.
nearfield::Emitter protocol_emitter(const photometry::DistributionPtr& d, double h, double angle) {
  photometry::LuminousOpening square;
  square.shape = photometry::LuminousOpening::Shape::rectangle;
  square.length = square.width = kEmitterSide;
  return nearfield::make_emitter(square, Vec3(0.0, 0.0, h),
                                 calc::rotation_xyz(kPi - angle, 0.0, 0.0), d);
}

struct Configuration {
  nearfield::Emitter emitter;
  Vec3 point;
};

// CPU time of the calling thread (s): on a shared machine wall time would count other processes'
// work, and each model runs on one thread, so thread CPU time is its cost.
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::string height_label(double h) { return format_double("%g", h); }

}  // namespace

std::vector<double> protocol_orientations() {
  return {kPi / 2, 5 * kPi / 8, 3 * kPi / 4, 7 * kPi / 8, kPi};
}

AccuracyModel AccuracyModel::rung(const nearfield::Model& model) {
  AccuracyModel m;
  m.name = nearfield::to_string(model);
  m.ladder = model;
  return m;
}
AccuracyModel AccuracyModel::structured_sampling() {
  AccuracyModel m;
  m.name = "structured sampling";
  m.kind = Kind::structured_sampling;
  return m;
}
AccuracyModel AccuracyModel::most_representative_point() {
  AccuracyModel m;
  m.name = "MRP";
  m.kind = Kind::most_representative_point;
  return m;
}
AccuracyModel AccuracyModel::monte_carlo(int samples) {
  AccuracyModel m;
  m.name = "MC " + std::to_string(samples);
  m.kind = Kind::monte_carlo;
  m.samples = std::max(1, samples);
  return m;
}

double evaluate(const AccuracyModel& model, const nearfield::Emitter& emitter, const Vec3& point,
                const Vec3& normal, std::uint64_t seed) {
  switch (model.kind) {
    case AccuracyModel::Kind::ladder:
      return nearfield::illuminance(emitter, point, normal, model.ladder);
    case AccuracyModel::Kind::structured_sampling:
      return structured_sampling_illuminance(emitter, point, normal);
    case AccuracyModel::Kind::most_representative_point:
      return mrp_illuminance(emitter, point, normal);
    case AccuracyModel::Kind::monte_carlo:
      return monte_carlo_illuminance(emitter, point, normal, model.samples, seed);
  }
  return 0.0;
}

std::vector<AccuracyModel> accuracy_models(bool quick) {
  using nearfield::Model;
  std::vector<AccuracyModel> out = {
      AccuracyModel::rung(Model::far_field()), AccuracyModel::structured_sampling(),
      AccuracyModel::most_representative_point(), AccuracyModel::rung(Model::paper_cubature())};
  for (int k = 1; k <= 3; ++k) out.push_back(AccuracyModel::rung(Model::subdivided(k)));
  for (int k = 1; k <= 3; ++k) out.push_back(AccuracyModel::rung(Model::lambert_subdivided(k)));
  out.push_back(AccuracyModel::rung(Model::adaptive(1e-3)));
  out.push_back(AccuracyModel::rung(Model::standard()));
  out.push_back(AccuracyModel::rung(Model::reference(1e-5)));
  const std::vector<int> mc =
      quick ? std::vector<int>{8, 64, 512}
            : std::vector<int>{8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
  for (int n : mc) out.push_back(AccuracyModel::monte_carlo(n));
  return out;
}

std::vector<std::filesystem::path> paper_ldt_files(const std::filesystem::path& ldt_dir) {
  // Luksch et al. 2020 Fig. 9 (../shared/photometry/MANIFEST.md lists the files).
  const char* names[] = {"zumtobel_arcos3_isym1",   "zumtobel_intro_isym0",
                         "zumtobel_linetik_isym3",  "zumtobel_mirel_isym4",
                         "zumtobel_panos_isym3",    "zumtobel_perluce_isym4",
                         "zumtobel_slotlight_isym4"};
  std::vector<std::filesystem::path> files;
  for (const char* n : names) files.push_back(ldt_dir / (std::string(n) + ".ldt"));
  return files;
}

std::vector<std::filesystem::path> contrast_files(const std::filesystem::path& ldt_dir) {
  // Files of a very different character from the paper's office luminaires, from the corpus
  // (tests/data/photometry, see its MANIFEST): a narrow spot (steep peak), an asymmetric
  // wall-washer-like flood (isym 0) and a roadway optic (strongly lateral, bilateral).
  const std::filesystem::path root = ldt_dir.parent_path();
  return {root / "ies" / "erco_qrcbc35_lm86_spot.ies",
          root / "ldt" / "ledvance_flmax_asym_isym0.ldt",
          root / "ies" / "rab_roadway_bilateral_lm02.ies"};
}

std::vector<AccuracyDataSet> accuracy_data_sets(const std::vector<std::filesystem::path>& files) {
  std::vector<AccuracyDataSet> sets;
  sets.push_back({"cosine", std::make_shared<photometry::LambertianDistribution>(kIntensityCd)});
  sets.push_back({"batwing", std::make_shared<nearfield::BatwingDistribution>(kIntensityCd)});
  for (const auto& f : files) {
    auto p = photometry::load_photometry_file(f);
    sets.push_back({f.stem().string(), p.distribution});
  }
  return sets;
}

double AccuracyStudy::mean_nrms(int m) const {
  double s = 0.0;
  int n = 0;
  for (const auto& c : cells)
    if (c.model_index == m) s += c.nrms, ++n;
  return n ? s / n : 0.0;
}

double AccuracyStudy::mean_ns(int m) const {
  double s = 0.0;
  int n = 0;
  for (const auto& c : cells)
    if (c.model_index == m) s += c.ns_per_eval, ++n;
  return n ? s / n : 0.0;
}

const AccuracyCell& AccuracyStudy::cell(const std::string& data_set, double height, int m) const {
  for (const auto& c : cells)
    if (c.data_set == data_set && c.height == height && c.model_index == m) return c;
  throw CalculationError("accuracy study: no cell for " + data_set +
                         " at h = " + height_label(height));
}

int monte_carlo_at_time(const AccuracyStudy& study, const std::string& data_set, double height,
                        double ns) {
  int best = -1;
  double best_d = INFINITY;
  for (int m = 0; m < static_cast<int>(study.models.size()); ++m) {
    if (!study.models[m].is_monte_carlo()) continue;
    const double d = std::abs(std::log(study.cell(data_set, height, m).ns_per_eval / ns));
    if (d < best_d) best_d = d, best = m;
  }
  return best;
}

AccuracyStudy run_accuracy_study(const std::vector<AccuracyDataSet>& data_sets,
                                 const std::vector<AccuracyModel>& models,
                                 const AccuracyOptions& options, const AccuracyProgress& progress) {
  AccuracyStudy study;
  study.options = options;
  study.models = models;
  const Vec3 up(0.0, 0.0, 1.0);
  const auto pts = receivers(options);
  const auto angles = protocol_orientations();
  double ref_seconds = 0.0;
  std::int64_t ref_count = 0;
  double cosine_max_rel = -1.0;

  for (const auto& ds : data_sets) {
    study.data_sets.push_back(ds.name);
    for (double h : options.heights) {
      if (progress) progress(ds.name + " h=" + height_label(h));
      std::vector<Configuration> configs;
      int centre_index = -1;
      for (double a : angles) {
        const auto e = protocol_emitter(ds.distribution, h, a);
        for (const auto& p : pts) configs.push_back({e, p});
        if (a == kPi) {  // the centre point: an extra configuration, excluded from the NRMS
          configs.push_back({e, Vec3(0.0, 0.0, 0.0)});
          centre_index = static_cast<int>(configs.size()) - 1;
        }
      }
      // The truth: converged reference, with its own error estimate.
      std::vector<double> truth(configs.size());
      const double t0 = thread_seconds();
      for (size_t i = 0; i < configs.size(); ++i) {
        const auto r = nearfield::reference_illuminance(configs[i].emitter, configs[i].point, up,
                                                        options.reference_tolerance);
        truth[i] = r.illuminance_lx;
        if (r.illuminance_lx > 0.0)
          study.reference_max_error_estimate =
              std::max(study.reference_max_error_estimate, r.error_estimate_lx / r.illuminance_lx);
      }
      ref_seconds += thread_seconds() - t0;
      ref_count += static_cast<std::int64_t>(configs.size());
      if (ds.name == "cosine") {  // the reference against the exact Lambert value (L = I0 / A)
        double max_t = 0.0;
        for (double t : truth) max_t = std::max(max_t, t);
        for (size_t i = 0; i < configs.size(); ++i) {
          const double exact =
              nearfield::lambert_uniform_illuminance(configs[i].emitter, configs[i].point, up,
                                                     kIntensityCd / (kEmitterSide * kEmitterSide));
          cosine_max_rel = std::max(cosine_max_rel, std::abs(truth[i] - exact) / max_t);
        }
      }
      double ref_sq = 0.0, ref_max = 0.0;
      int n = 0;
      for (size_t i = 0; i < configs.size(); ++i) {
        if (static_cast<int>(i) == centre_index) continue;
        ref_sq += truth[i] * truth[i];
        ref_max = std::max(ref_max, truth[i]);
        ++n;
      }
      study.points_per_cell = n;
      const double ref_rms = std::sqrt(ref_sq / n);

      std::vector<double> values(configs.size());
      for (int m = 0; m < static_cast<int>(models.size()); ++m) {
        const double t1 = thread_seconds();
        for (size_t i = 0; i < configs.size();
             ++i)  // seed: independent Monte Carlo noise per point
          values[i] = evaluate(models[m], configs[i].emitter, configs[i].point, up, i + 1);
        const double secs = thread_seconds() - t1;
        double err_sq = 0.0, max_abs = 0.0, point_rel = 0.0;
        for (size_t i = 0; i < configs.size(); ++i) {
          if (static_cast<int>(i) == centre_index) continue;
          const double d = values[i] - truth[i];
          err_sq += d * d;
          max_abs = std::max(max_abs, std::abs(d));
          if (truth[i] >= kPointErrorFloor * ref_max && truth[i] > 0.0)
            point_rel = std::max(point_rel, std::abs(d) / truth[i]);
        }
        AccuracyCell c;
        c.data_set = ds.name;
        c.height = h;
        c.model = models[m].name;
        c.model_index = m;
        c.nrms = ref_rms > 0.0 ? std::sqrt(err_sq / n) / ref_rms : 0.0;
        c.max_rel = ref_max > 0.0 ? max_abs / ref_max : 0.0;
        c.point_rel = point_rel;
        const double tc = truth[centre_index];
        c.centre_rel = tc > 0.0 ? values[centre_index] / tc - 1.0 : 0.0;
        c.ns_per_eval = 1e9 * secs / static_cast<double>(configs.size());
        study.cells.push_back(c);
      }
    }
  }
  study.reference_ns_per_eval =
      ref_count ? 1e9 * ref_seconds / static_cast<double>(ref_count) : 0.0;
  study.cosine_vs_lambert_max_rel = cosine_max_rel;
  return study;
}

std::string format_accuracy_markdown(const AccuracyStudy& s, const std::string& command) {
  std::ostringstream o;
  const auto& op = s.options;
  o << "Generated by `" << command << "`: " << s.data_sets.size() << " data sets x "
    << op.heights.size() << " heights, " << s.points_per_cell << " receivers per cell (" << op.grid
    << " x " << op.grid << " over " << op.region << " x " << op.region
    << ", 5 orientations stitched). Truth: reference integrator at rel. tolerance "
    << format_double("%.0e", op.reference_tolerance) << " ("
    << format_double("%.0f", s.reference_ns_per_eval / 1e3)
    << " us per point; largest reported relative error estimate "
    << format_double("%.1e", s.reference_max_error_estimate) << ")";
  if (s.cosine_vs_lambert_max_rel >= 0.0)
    o << "; on the cosine data set it differs from the exact Lambert value by at most "
      << format_double("%.1e", s.cosine_vs_lambert_max_rel) << " of the cell's maximum";
  o << ".\n\n";

  o << "### All models (mean over data sets and heights)\n\n"
    << "| model | ns / evaluation | mean NRMS | worst NRMS | worst error / max E | worst point "
       "error (E >= "
    << format_double("%g", kPointErrorFloor)
    << " max E) | centre error, cosine h = " << height_label(op.heights.front())
    << " |\n|---|---:|---:|---:|---:|---:|---:|\n";
  for (int m = 0; m < static_cast<int>(s.models.size()); ++m) {
    double worst = 0.0, worst_max = 0.0, worst_point = 0.0;
    for (const auto& c : s.cells)
      if (c.model_index == m)
        worst = std::max(worst, c.nrms), worst_max = std::max(worst_max, c.max_rel),
        worst_point = std::max(worst_point, c.point_rel);
    const auto& cc = s.cell(s.data_sets.front(), op.heights.front(), m);
    o << "| " << s.models[m].name << " | " << format_double("%.0f", s.mean_ns(m)) << " | "
      << format_double("%.2e", s.mean_nrms(m)) << " | " << format_double("%.2e", worst) << " | "
      << format_double("%.2e", worst_max) << " | " << format_double("%.2e", worst_point) << " | "
      << format_double("%+.2f %%", 100 * cc.centre_rel) << " |\n";
  }

  auto index_of = [&](const std::string& name) {
    for (int m = 0; m < static_cast<int>(s.models.size()); ++m)
      if (s.models[m].name == name) return m;
    return -1;
  };
  using nearfield::Model;
  const int paper = index_of(nearfield::to_string(Model::paper_cubature()));
  std::vector<int> cols;
  for (const Model& model :
       {Model::far_field(), Model::paper_cubature(), Model::subdivided(1), Model::subdivided(2),
        Model::subdivided(3), Model::lambert_subdivided(1), Model::lambert_subdivided(2),
        Model::lambert_subdivided(3), Model::standard()}) {
    const int m = index_of(nearfield::to_string(model));
    if (m >= 0) cols.push_back(m);
  }
  o << "\n### NRMS per data set and height: the [Luksch2020] cubature, the subdivided rungs, and "
       "Monte "
       "Carlo at the cubature's time\n\n| data set | h |";
  for (int m : cols) o << " " << s.models[m].name << " |";
  if (paper >= 0) o << " MC at paper's time |";
  o << "\n|---|---:|";
  for (size_t i = 0; i < cols.size() + (paper >= 0 ? 1 : 0); ++i) o << "---:|";
  o << "\n";
  for (const auto& ds : s.data_sets) {
    for (double h : op.heights) {
      o << "| " << ds << " | " << height_label(h) << " |";
      for (int m : cols) o << " " << format_double("%.2e", s.cell(ds, h, m).nrms) << " |";
      if (paper >= 0) {
        const int mc = monte_carlo_at_time(s, ds, h, s.cell(ds, h, paper).ns_per_eval);
        if (mc >= 0) {
          const auto& c = s.cell(ds, h, mc);
          o << " " << format_double("%.2e", c.nrms) << " (" << c.model << ", "
            << format_double("%.0f", c.ns_per_eval) << " ns) |";
        } else {
          o << " – |";
        }
      }
      o << "\n";
    }
  }
  return o.str();
}

void write_accuracy_plot(const AccuracyStudy& s, const std::filesystem::path& png) {
  constexpr int kW = 960, kH = 640, kLeft = 90, kRight = 30, kTop = 50, kBottom = 70;
  struct P {
    double x, y;  // log10 ns, log10 nrms
    std::string label;
    bool mc;
  };
  std::vector<P> pts;
  for (int m = 0; m < static_cast<int>(s.models.size()); ++m) {
    const double ns = std::max(1.0, s.mean_ns(m));
    const double e = std::max(kPlotNrmsFloor, s.mean_nrms(m));
    pts.push_back({std::log10(ns), std::log10(e), s.models[m].name, s.models[m].is_monte_carlo()});
  }
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& p : pts)
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  x0 = std::floor(x0), x1 = std::ceil(x1 + 0.3), y0 = std::floor(y0), y1 = std::ceil(y1);
  if (x1 <= x0) x1 = x0 + 1;
  if (y1 <= y0) y1 = y0 + 1;
  auto px = [&](double x) {
    return kLeft + static_cast<int>(std::lround((x - x0) / (x1 - x0) * (kW - kLeft - kRight)));
  };
  auto py = [&](double y) {
    return kTop + static_cast<int>(std::lround((y1 - y) / (y1 - y0) * (kH - kTop - kBottom)));
  };

  using report::Rgb;
  const Rgb white{1, 1, 1}, black{0, 0, 0}, grey{0.85f, 0.85f, 0.85f}, blue{0.1f, 0.3f, 0.8f},
      red{0.85f, 0.15f, 0.1f}, green{0.1f, 0.6f, 0.2f};
  report::Raster canvas(kW, kH, white);
  bool text_ok = true;
  auto text = [&](int x, int y, const std::string& t, int size, Rgb colour) {
    if (text_ok) text_ok = report::draw_text(canvas, x, y, t, size, report::kPlotFont, colour);
  };
  for (int d = static_cast<int>(x0); d <= static_cast<int>(x1); ++d) {
    canvas.line(px(d), py(y0), px(d), py(y1), grey);
    text(px(d) - 14, py(y0) + 22, "1e" + std::to_string(d), 14, black);
  }
  for (int d = static_cast<int>(y0); d <= static_cast<int>(y1); ++d) {
    canvas.line(px(x0), py(d), px(x1), py(d), grey);
    text(20, py(d) + 5, "1e" + std::to_string(d), 14, black);
  }
  canvas.box(px(x0), py(y1), px(x1), py(y0), black, false);
  text(kLeft, 30, "Near-field models: NRMS error vs time (mean over data sets and heights)", 18,
       black);
  text(kW / 2 - 120, kH - 18, "time per evaluation (ns, one thread)", 15, black);
  text(8, kTop - 12, "NRMS", 15, black);

  // Pareto front: sorted by time, keep the models more accurate than every faster one.
  std::vector<P> sorted = pts;
  std::sort(sorted.begin(), sorted.end(), [](const P& a, const P& b) { return a.x < b.x; });
  std::vector<P> front;
  for (const auto& p : sorted)
    if (front.empty() || p.y < front.back().y) front.push_back(p);
  for (size_t i = 1; i < front.size(); ++i)
    canvas.line(px(front[i - 1].x), py(front[i - 1].y), px(front[i].x), py(front[i].y), green);
  for (size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    const int cx = px(p.x), cy = py(p.y);
    canvas.fill(cx - 4, cx + 5, cy - 4, cy + 5, p.mc ? red : blue);
    // Monte Carlo labels to the left, the ladder's to the right, staggered against overlap.
    const int dy = (i % 2) ? 14 : -4;
    if (p.mc)
      text(cx - 8 - 7 * static_cast<int>(p.label.size()), cy + dy, p.label, 12, red);
    else
      text(cx + 8, cy + dy, p.label, 12, blue);
  }
  text(kW - kRight - 260, kTop + 22, "blue: quadrature ladder, red: Monte Carlo", 13, black);
  text(kW - kRight - 260, kTop + 40, "green: Pareto front", 13, green);
  if (!text_ok)
    std::fprintf(stderr,
                 "luxgrid: warning: %s: plot written without labels (font %s unavailable)\n",
                 png.string().c_str(), report::kPlotFont);
  const std::filesystem::path tmp = png.string() + ".tmp.png";
  report::write_png(canvas, tmp);
  std::filesystem::rename(tmp, png);
}

}  // namespace luxgrid::study
