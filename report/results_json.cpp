#include "report/results_json.h"

namespace luxgrid::report {

namespace {
nlohmann::json vec3(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

const char* kind_name(geometry::SurfaceGrid::Kind k) {
  switch (k) {
    case geometry::SurfaceGrid::Kind::grid: return "grid";
    case geometry::SurfaceGrid::Kind::points: return "points";
    case geometry::SurfaceGrid::Kind::observers: return "observers";
  }
  return "?";
}

// Per observer its views: line of sight, UGR (null when no luminaire counts), background
// luminance (cd/m2), the indirect illuminance it comes from, and each counted luminaire's term.
nlohmann::json observers_json(const std::vector<calc::glare::ObserverResult>& observers) {
  using nlohmann::json;
  json out = json::array();
  for (const auto& o : observers) {
    json views = json::array();
    for (const auto& v : o.views) {
      json terms = json::array();
      for (const auto& t : v.terms) {
        terms.push_back({{"luminaire", t.luminaire}, {"L", t.term.L_cd_m2}, {"omega", t.term.omega_sr},
                         {"p", t.term.p}});
      }
      views.push_back({{"direction", vec3(v.direction)},
                       {"UGR", v.UGR ? json(*v.UGR) : json(nullptr)},
                       {"Lb", v.Lb_cd_m2},
                       {"E_indirect", v.E_indirect_lx},
                       {"terms", std::move(terms)}});
    }
    out.push_back({{"at", vec3(o.at)}, {"views", std::move(views)}});
  }
  return out;
}

nlohmann::json surface_json(const calc::SurfaceResult& r) {
  using nlohmann::json;
  const auto& g = r.grid;
  json s;
  s["name"] = g.name;
  s["kind"] = kind_name(g.kind);
  s["size"] = json::array({g.nu, g.nv});
  if (g.kind == geometry::SurfaceGrid::Kind::grid) {
    s["spacing"] = json::array({g.spacing_u, g.spacing_v});
  }
  // What geometry did to the grid: the quantity its numbers are, and the points it kept in the
  // nu x nv layout but left out of the calculation and the statistics (their E is 0).
  s["quantity"] = geometry::to_string(g.quantity);
  s["points_outside"] = g.points_outside;
  s["points_in_obstacles"] = g.points_in_obstacles;
  json points = json::array(), normals = json::array();
  for (size_t i = 0; i < g.points.size(); ++i) {
    points.push_back(vec3(g.points[i]));
    normals.push_back(vec3(g.normals[i]));
  }
  s["points"] = std::move(points);
  s["normals"] = std::move(normals);
  // false for the points left out above: their E is 0 and the statistics skip them.
  json active = json::array();
  for (size_t i = 0; i < g.points.size(); ++i) active.push_back(g.active.empty() || g.active[i]);
  s["active"] = std::move(active);
  s["E"] = r.E;
  s["E_direct"] = r.E_direct;
  s["E_indirect"] = r.E_indirect;
  s["stats"] = {{"Emin", r.stats.Emin}, {"Eavg", r.stats.Eavg}, {"Emax", r.stats.Emax},
                {"U0", r.stats.U0}, {"Ud", r.stats.Ud}};
  if (g.kind == geometry::SurfaceGrid::Kind::observers) {
    s["UGR_max"] = r.UGR_max ? json(*r.UGR_max) : json(nullptr);
    s["observers"] = observers_json(r.observers);
  }
  return s;
}
}  // namespace

nlohmann::json results_to_json(const calc::Results& results, const std::vector<std::string>& warnings,
                               const ResultsOrigin& origin) {
  using nlohmann::json;
  json j;
  j["format"] = kResultsFormat;
  j["luxgrid_version"] = origin.version;
  j["project"] = results.project;
  j["project_sha256"] = origin.project_sha256;
  j["quality"] = calc::to_string(results.quality);
  j["maintenance_factor"] = results.maintenance_factor;
  // Every E, E_direct and E_indirect below: E = E_direct + E_indirect, all times the factor.
  j["values"] = "maintained";
  j["plan"] = {{"direct", results.plan.direct},
               {"indirect", results.plan.indirect},
               {"visibility", results.plan.visibility},
               {"notes", results.plan.notes},
               {"promise", results.plan.promise}};
  // The plan's own error estimate per surface (calc/plan_estimates.h), relative; null where a
  // part was not estimated (no reflected light; the far field everywhere).
  json estimates = json::array();
  const auto share = [](double v) { return v < 0.0 ? json(nullptr) : json(v); };
  for (const auto& e : results.plan.estimates)
    estimates.push_back({{"surface", e.surface},
                         {"direct", share(e.direct)},
                         {"patch_size", share(e.patch_size)},
                         {"bounces", share(e.bounces)},
                         {"probe_points", e.probe_points},
                         {"total", e.total()}});
  j["plan"]["estimates"] = std::move(estimates);
  // Warnings: the scene's and the outputs' (given), then the plan's (an estimate above the
  // promise).
  json all_warnings = warnings;
  for (const auto& w : results.plan.warnings) all_warnings.push_back(w);
  j["warnings"] = std::move(all_warnings);
  j["surfaces"] = json::array();
  for (const auto& s : results.surfaces) j["surfaces"].push_back(surface_json(s));
  return j;
}

nlohmann::json timing_to_json(const calc::Results& results) {
  nlohmann::json j;
  j["timing_s"] = nlohmann::json::object();
  for (const auto& [phase, seconds] : results.timing_s) j["timing_s"][phase] = seconds;
  return j;
}

}  // namespace luxgrid::report
