#include "report/write_outputs.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <ctime>

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "calc/statistics.h"
#include "report/csv.h"
#include "report/energy.h"
#include "report/false_colour.h"
#include "report/html_report.h"
#include "report/results_document.h"
#include "report/results_json.h"
#include "report/scene_glb.h"
#include "report/surface_npy.h"
#include "util/error.h"
#include "util/ordered_tasks.h"
#include "util/output_names.h"

namespace luxgrid::report {

namespace {

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
  report.en17037 = options.en17037;
  report.version = options.version;
  report.date = utc_now();
  // Asked for (--part-plots) and when indirect light ran (any point received some), each grid
  // also gets its direct and indirect parts as <surface>_direct.png and <surface>_indirect.png
  // (maintained values, like the CSV's E_direct_maintained_lx / E_indirect_maintained_lx
  // columns; each on its own scale unless a scale was given, since the indirect part is often a
  // small fraction of the total). Not by default: they are two thirds of the plotting, and the
  // CSV holds both parts at every point.
  bool indirect_ran = false;
  for (const auto& s : results.surfaces)
    for (double e : s.E_indirect) indirect_ran = indirect_ran || e > 0.0;
  const bool parts_plotted = options.part_plots && indirect_ran;
  // Every file of every surface is independent of the others: they are written in parallel, one
  // task per CSV or array and one per surface's plots, which draws its two or three plots in
  // parallel again after working out once what each pixel of its map shows (map_samples). The
  // report's luminaire sections (polar diagrams, CIE 190 tables) are a task of their own, the
  // first one, so what is left after the plots is assembling text. The longest tasks are taken
  // first and one at a time (the luminaires, the plots, then the CSVs and arrays, which take a
  // fraction of a plot's time), so the last task to finish is a short one and no thread waits
  // long for another at the end. The warnings are gathered in surface order afterwards, so the
  // output does not depend on the schedule.
  struct Job {
    std::size_t surface;
    enum class What { luminaires_html, csv, npy, plots } what;
    std::array<std::string, 3> warnings;  // plots: the total's, the direct part's, the reflected's
    std::string png;                      // plots, for report.html: the total's file as written
  };
  std::vector<Job> jobs;
  // The luminaire types' data goes into results.json, and with the report their sections.
  std::vector<LuminaireType> types = options.types ? *options.types : std::vector<LuminaireType>{};
  const bool make_types = !options.types && options.scene && !options.scene->photometry.empty();
  if (make_types || (options.report && options.scene && !types.empty()))
    jobs.push_back({0, Job::What::luminaires_html, {}, {}});
  for (std::size_t i = 0; i < results.surfaces.size(); ++i)
    if (results.surfaces[i].grid.kind == geometry::SurfaceGrid::Kind::grid)
      jobs.push_back({i, Job::What::plots, {}, {}});
  for (std::size_t i = 0; i < results.surfaces.size(); ++i) {
    jobs.push_back({i, Job::What::csv, {}, {}});
    if (options.arrays_npy) jobs.push_back({i, Job::What::npy, {}, {}});
  }
  // The direct (part 1) or reflected (part 2) light of a surface as a result of its own.
  auto part_of = [](const calc::SurfaceResult& s, int part) {
    const bool direct = part == 1;
    calc::SurfaceResult p;
    p.grid = s.grid;
    p.grid.name = s.grid.name + (direct ? " (direct)" : " (indirect)");
    p.E = direct ? s.E_direct : s.E_indirect;
    p.E_direct = s.E_direct;
    p.E_indirect = s.E_indirect;
    p.stats = calc::compute_statistics(p.E, s.grid.active);
    return p;
  };
  const auto run_job = [&](Job& job) {
    if (job.what == Job::What::luminaires_html) {
      if (make_types)
        types = luminaire_types(*options.scene, results.plan.indirect_decision.luminous_flux_lm);
      if (options.report) report.luminaires_html = luminaire_sections_html(types, *options.scene);
      return;
    }
    const calc::SurfaceResult& s = results.surfaces[job.surface];
    const SurfaceOutputFiles names = surface_output_files(s.grid.name);
    switch (job.what) {
      case Job::What::luminaires_html: return;
      case Job::What::csv:
        return write_file_streamed(folder.file(names.csv),
                                   [&](std::ostream& out) { write_surface_csv(out, s); });
      case Job::What::npy: return write_text_file(folder.file(names.npy), surface_npy(s));
      case Job::What::plots: {
        const int parts = parts_plotted ? 3 : 1;
        const auto samples = parts > 1 ? map_samples(s, options.scene) : nullptr;
        tbb::parallel_for(0, parts, [&](int part) {
          if (part == 0) {
            const ColourScale scale =
                options.scale ? *options.scale : fit_scale(s.stats.Emin, s.stats.Emax);
            job.warnings[0] =
                write_false_colour_png(s, scale, folder.file(names.png), overlay_for(s), nullptr,
                                       samples.get(), options.report ? &job.png : nullptr);
            return;
          }
          const calc::SurfaceResult p = part_of(s, part);
          const ColourScale scale =
              options.scale ? *options.scale : fit_scale(p.stats.Emin, p.stats.Emax);
          job.warnings[part] = write_false_colour_png(
              p, scale, folder.file(part == 1 ? names.direct_png : names.indirect_png), overlay,
              nullptr, samples.get());
        });
        return;
      }
    }
  };
  // Taken in the list's order (util/ordered_tasks.h): a parallel loop would split the list in
  // halves, and the plots of one half could be left to one thread at the end.
  run_in_list_order(jobs.size(), [&](std::size_t n) { run_job(jobs[n]); });
  for (Job& job : jobs) {
    for (const std::string& w : job.warnings)
      if (!w.empty() && std::find(warnings.begin(), warnings.end(), w) == warnings.end())
        warnings.push_back(w);
    if (job.what == Job::What::plots && options.report)
      report.png[results.surfaces[job.surface].grid.name] = std::move(job.png);
  }
  if (options.scene) {
    report.energy = room_energy(*options.scene, types, results, options.checks);
    report.rooms = room_figures(*options.scene);
  }
  report.types = types;
  // scene.glb, from what results.json keeps (report_input), so `luxgrid report` writes it again
  // byte for byte; report.html embeds the same bytes for its 3D view.
  std::string glb;
  if (options.scene) {
    SceneGlbInput scene_in;
    scene_in.scene = options.scene;
    scene_in.results = &results;
    scene_in.types = &types;
    scene_in.scale = options.scale;
    scene_in.version = options.version;
    glb = scene_glb(scene_in);
    report.scene_glb = &glb;
  }
  // report.html and results.json side by side: neither reads the other.
  const auto write_html = [&] {
    if (options.scene) write_text_file(folder.file(kSceneFile), glb);
    if (options.report)
      write_file_streamed(folder.file(kReportFile), [&](std::ostream& out) {
        write_html_report(report, [&](std::string_view s) {
          out.write(s.data(), static_cast<std::streamsize>(s.size()));
        });
      });
  };
  const auto write_json = [&] {
    if (options.results_json)
      return write_text_file(folder.file(kResultsFile), *options.results_json);
    nlohmann::json j = results_document(results, options.scene, options.checks, types, warnings,
                                        options.version, options.en17037);
    write_file_streamed(folder.file(kResultsFile),
                        [&](std::ostream& out) { write_results_json(out, j, results); });
  };
  // results.json on this thread, whose allocator arena holds the memory the calculation freed
  // (on another thread its text would be fresh memory, a page fault a page); the page, written
  // a few kilobytes at a time, on a worker.
  // Either one's error is thrown once both have stopped.
  tbb::task_group html;
  html.run(write_html);
  try {
    write_json();
  } catch (...) {
    html.wait();
    throw;
  }
  html.wait();
  results.timing_s.emplace_back(
      "report", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  write_text_file(folder.file(kTimingFile), timing_to_json(results).dump(1) + "\n");
  return warnings;
}

}  // namespace luxgrid::report
