#include "report/write_outputs.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>

#include <tbb/parallel_for.h>

#include "calc/statistics.h"
#include "report/csv.h"
#include "report/false_colour.h"
#include "report/html_report.h"
#include "report/results_json.h"
#include "report/surface_npy.h"
#include "util/error.h"
#include "util/output_names.h"

namespace luxgrid::report {

namespace {

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw CalculationError(p.string() + ": cannot read back the image");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The calculation's date for the report: now, or SOURCE_DATE_EPOCH (seconds since 1970, the
// reproducible-builds convention) when set, so that two runs can write byte-identical reports.
std::string utc_now() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long v = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && v >= 0) t = static_cast<std::time_t>(v);
  }
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M UTC", &tm);
  return buf;
}

}  // namespace

std::vector<std::string> write_outputs(calc::Results& results, const OutputFolder& folder) {
  return write_outputs(results, folder, OutputOptions{});
}

std::vector<std::string> write_outputs(calc::Results& results, const OutputFolder& folder,
                                       const OutputOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> warnings;
  PlotOverlay overlay;
  overlay.scene = options.scene;
  // Each surface's stated illuminance requirements (Em, Emin) get an isolux line of their own.
  auto overlay_for = [&](const calc::SurfaceResult& s) {
    PlotOverlay o = overlay;
    for (const auto& c : options.checks)
      if (c.surface == s.grid.name && (c.quantity == "Em" || c.quantity == "Emin"))
        o.required_lx.push_back(c.required);
    return o;
  };
  ReportInput report;
  report.results = &results;
  report.scene = options.scene;
  report.checks = options.checks;
  report.cost = options.cost;
  report.version = options.version;
  report.date = utc_now();
  // Indirect light ran when any point received some: then each grid also gets its direct and
  // indirect parts as <surface>_direct.png and <surface>_indirect.png (maintained values, like the
  // CSV's E_direct_maintained_lx / E_indirect_maintained_lx columns; each on its own scale
  // unless a scale was given, since the indirect part is often a small fraction of the total).
  bool indirect_ran = false;
  for (const auto& s : results.surfaces)
    for (double e : s.E_indirect) indirect_ran = indirect_ran || e > 0.0;
  // Every file of every surface is independent of the others: they are written in parallel, one
  // task per file (a surface's plots are the largest share), and the warnings are gathered in
  // surface order afterwards so the output does not depend on the schedule. The report's
  // luminaire sections (polar diagrams, CIE 190 tables) are made by a task of their own
  // meanwhile, the first one, so what is left after the plots is assembling text.
  struct Job {
    std::size_t surface;
    enum class What { luminaires_html, csv, npy, plot, direct_plot, indirect_plot } what;
    std::string warning;
  };
  std::vector<Job> jobs;
  if (options.report && options.scene && !options.scene->photometry.empty())
    jobs.push_back({0, Job::What::luminaires_html, {}});
  for (std::size_t i = 0; i < results.surfaces.size(); ++i) {
    jobs.push_back({i, Job::What::csv, {}});
    if (options.arrays_npy) jobs.push_back({i, Job::What::npy, {}});
    if (results.surfaces[i].grid.kind != geometry::SurfaceGrid::Kind::grid) continue;
    jobs.push_back({i, Job::What::plot, {}});
    if (indirect_ran) {
      jobs.push_back({i, Job::What::direct_plot, {}});
      jobs.push_back({i, Job::What::indirect_plot, {}});
    }
  }
  tbb::parallel_for(std::size_t{0}, jobs.size(), [&](std::size_t n) {
    Job& job = jobs[n];
    if (job.what == Job::What::luminaires_html) {
      report.luminaires_html = luminaire_sections_html(*options.scene);
      return;
    }
    const calc::SurfaceResult& s = results.surfaces[job.surface];
    const SurfaceOutputFiles names = surface_output_files(s.grid.name);
    switch (job.what) {
      case Job::What::luminaires_html: return;
      case Job::What::csv: return write_text_file(folder.file(names.csv), surface_csv(s));
      case Job::What::npy: return write_text_file(folder.file(names.npy), surface_npy(s));
      case Job::What::plot: {
        const ColourScale scale =
            options.scale ? *options.scale : fit_scale(s.stats.Emin, s.stats.Emax);
        job.warning = write_false_colour_png(s, scale, folder.file(names.png), overlay_for(s));
        return;
      }
      case Job::What::direct_plot:
      case Job::What::indirect_plot: {
        const bool direct = job.what == Job::What::direct_plot;
        calc::SurfaceResult part;
        part.grid = s.grid;
        part.grid.name = s.grid.name + (direct ? " (direct)" : " (indirect)");
        part.E = direct ? s.E_direct : s.E_indirect;
        part.E_direct = s.E_direct;
        part.E_indirect = s.E_indirect;
        part.stats = calc::compute_statistics(part.E, s.grid.active);
        const ColourScale part_scale =
            options.scale ? *options.scale : fit_scale(part.stats.Emin, part.stats.Emax);
        job.warning = write_false_colour_png(
            part, part_scale, folder.file(direct ? names.direct_png : names.indirect_png), overlay);
        return;
      }
    }
  });
  for (const Job& job : jobs) {
    if (!job.warning.empty() &&
        std::find(warnings.begin(), warnings.end(), job.warning) == warnings.end())
      warnings.push_back(job.warning);
    if (job.what == Job::What::plot && options.report) {
      const calc::SurfaceResult& s = results.surfaces[job.surface];
      report.png[s.grid.name] = read_bytes(folder.file(surface_output_files(s.grid.name).png));
    }
  }
  if (options.report) write_text_file(folder.file(kReportFile), html_report(report));
  results.timing_s.emplace_back(
      "report", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  // The scene's warnings (legal but suspicious input) and the outputs', as the terminal shows them.
  std::vector<std::string> all_warnings =
      options.scene ? options.scene->warnings : std::vector<std::string>{};
  all_warnings.insert(all_warnings.end(), warnings.begin(), warnings.end());
  ResultsOrigin origin;
  origin.version = options.version;
  if (options.scene) origin.project_sha256 = options.scene->project_sha256;
  // Without the point arrays: write_results_json streams them from `results`.
  nlohmann::json j = results_outline_json(results, all_warnings, origin);
  if (options.scene) {
    // The maintenance factor every E includes, and its parts when the project gave them [CIE97].
    const auto& settings = options.scene->settings;
    nlohmann::json m = {{"factor", settings.maintenance_factor}};
    if (const auto& p = settings.maintenance_parts) {
      m["LLMF"] = p->LLMF;
      m["LSF"] = p->LSF;
      m["LMF"] = p->LMF;
      m["RSMF"] = p->RSMF;
    }
    j["maintenance"] = std::move(m);
  }
  if (!options.checks.empty()) {
    // Per surface, each requirement with its verdict and margin; at the top, the overall verdict.
    for (auto& s : j["surfaces"]) {
      for (const auto& c : options.checks) {
        if (c.surface == s["name"]) s["requirements"].push_back(check_to_json(c));
      }
    }
    j["requirements_met"] = all_met(options.checks);
  }
  write_file_streamed(folder.file(kResultsFile),
                      [&](std::ostream& out) { write_results_json(out, j, results); });
  write_text_file(folder.file(kTimingFile), timing_to_json(results).dump(1) + "\n");
  return warnings;
}

}  // namespace luxgrid::report
