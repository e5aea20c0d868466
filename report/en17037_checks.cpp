#include "report/en17037_checks.h"

#include <cstdio>

#include "report/json_fields.h"
#include "util/error.h"
#include "util/format.h"

namespace luxgrid::report {

using daylight::En17037Assessment;
using daylight::En17037Criterion;
using daylight::En17037PlaneResult;

std::optional<En17037Assessment> assess_en17037(const calc::Results& results,
                                                const calc::Scene& scene) {
  if (results.scene != calc::LightingScene::daylight || !scene.daylight || !scene.daylight->en17037)
    return std::nullopt;
  const daylight::En17037Request& request = *scene.daylight->en17037;
  En17037Assessment a;
  a.median_external_diffuse_lx = request.median_external_diffuse_lx;
  a.asked = request.level;
  for (const daylight::En17037PlaneRef& plane : request.planes) {
    const calc::SurfaceResult* found = nullptr;
    for (const auto& s : results.surfaces)
      if (s.grid.name == plane.surface) found = &s;
    if (!found)
      throw InputError("EN 17037: no calculation surface named \"" + plane.surface + "\"");
    a.planes.push_back(daylight::assess_en17037_plane(plane.surface, found->DF, found->grid.active,
                                                      plane.top_lit,
                                                      request.median_external_diffuse_lx));
  }
  return a;
}

namespace {

RequirementCheck en17037_check(const En17037Assessment& a, const En17037PlaneResult& p,
                               const En17037Criterion& c, const char* quantity) {
  RequirementCheck r;
  r.surface = p.surface;
  r.role = "reference plane";
  r.quantity = quantity;
  r.required = 100.0 * c.required_fraction;
  r.achieved = 100.0 * c.fraction;
  r.calculated = p.points > 0;
  r.met = c.met;
  r.margin = r.achieved - r.required;
  r.margin_rel = r.margin / r.required;
  r.source = std::string("EN 17037:2018 Annex A, ") + daylight::to_string(a.asked) + " level";
  r.fixed_by_standard = true;
  r.note = "DF >= " + format_double("%.2f", c.daylight_factor_percent) + " % (" +
           number_text(c.illuminance_lx) + " lx at " + number_text(a.median_external_diffuse_lx) +
           " lx outside)" + (p.top_lit ? "; top-lit" : "");
  if (!r.calculated) r.note = "no active point on the plane";
  return r;
}

nlohmann::json criterion_json(const En17037Criterion& c) {
  return {{"illuminance_lx", c.illuminance_lx},
          {"DF", c.daylight_factor_percent},
          {"required_fraction", c.required_fraction},
          {"fraction", c.fraction},
          {"met", c.met}};
}

En17037Criterion criterion_from_json(const nlohmann::json& j) {
  En17037Criterion c;
  read_fields(j, "illuminance_lx", c.illuminance_lx, "DF", c.daylight_factor_percent,
              "required_fraction", c.required_fraction, "fraction", c.fraction, "met", c.met);
  return c;
}

daylight::En17037Level level_from_json(const nlohmann::json& j) {
  const auto level = daylight::en17037_level_from_name(j.get<std::string>());
  if (!level) throw nlohmann::json::other_error::create(501, "unknown EN 17037 level", &j);
  return *level;
}

}  // namespace

std::vector<RequirementCheck> en17037_checks(const En17037Assessment& a) {
  std::vector<RequirementCheck> out;
  for (const En17037PlaneResult& p : a.planes) {
    const auto& level = p.levels[static_cast<std::size_t>(a.asked)];
    out.push_back(en17037_check(a, p, level.target, kEn17037TargetQuantity));
    out.push_back(en17037_check(a, p, level.minimum_target, kEn17037MinimumTargetQuantity));
  }
  return out;
}

nlohmann::json en17037_to_json(const En17037Assessment& a) {
  nlohmann::json j = {{"method", "daylight factor"},
                      {"median_external_diffuse_lx", a.median_external_diffuse_lx},
                      {"level_asked", daylight::to_string(a.asked)},
                      {"planes", nlohmann::json::array()}};
  bool met = true;
  for (const En17037PlaneResult& p : a.planes) {
    nlohmann::json levels = nlohmann::json::array();
    for (const auto& l : p.levels)
      levels.push_back({{"level", daylight::to_string(l.level)},
                        {"met", l.met},
                        {"target", criterion_json(l.target)},
                        {"minimum_target", criterion_json(l.minimum_target)}});
    met = met && p.levels[static_cast<std::size_t>(a.asked)].met;
    j["planes"].push_back(
        {{"surface", p.surface},
         {"top_lit", p.top_lit},
         {"points", p.points},
         {"DF_average", p.DF_average_percent},
         {"DF_min", p.DF_min_percent},
         {"uniformity", p.uniformity},
         {"level_achieved",
          p.achieved ? nlohmann::json(daylight::to_string(*p.achieved)) : nlohmann::json(nullptr)},
         {"levels", std::move(levels)}});
  }
  j["met"] = met;
  return j;
}

En17037Assessment en17037_from_json(const nlohmann::json& j) {
  En17037Assessment a;
  j.at("median_external_diffuse_lx").get_to(a.median_external_diffuse_lx);
  a.asked = level_from_json(j.at("level_asked"));
  for (const nlohmann::json& pj : j.at("planes")) {
    En17037PlaneResult p;
    read_fields(pj, "surface", p.surface, "top_lit", p.top_lit, "points", p.points, "DF_average",
                p.DF_average_percent, "DF_min", p.DF_min_percent, "uniformity", p.uniformity);
    if (!pj.at("level_achieved").is_null()) p.achieved = level_from_json(pj.at("level_achieved"));
    const nlohmann::json& levels = pj.at("levels");
    if (levels.size() != p.levels.size())
      throw nlohmann::json::other_error::create(501, "three EN 17037 levels expected", &levels);
    for (std::size_t k = 0; k < p.levels.size(); ++k) {
      const nlohmann::json& lj = levels.at(k);
      p.levels[k].level = level_from_json(lj.at("level"));
      lj.at("met").get_to(p.levels[k].met);
      p.levels[k].target = criterion_from_json(lj.at("target"));
      p.levels[k].minimum_target = criterion_from_json(lj.at("minimum_target"));
    }
    a.planes.push_back(std::move(p));
  }
  return a;
}

std::string format_en17037(const En17037Assessment& a) {
  std::string out = "EN 17037 daylight provision (daylight-factor method, E_v,d,med " +
                    number_text(a.median_external_diffuse_lx) +
                    " lx, level asked: " + daylight::to_string(a.asked) + "):\n";
  char line[400];
  for (const En17037PlaneResult& p : a.planes) {
    std::snprintf(line, sizeof line,
                  "  %s (%s, %zu points): DF average %.2f %%, minimum %.2f %%, uniformity %.3f; "
                  "level reached: %s\n",
                  p.surface.c_str(), p.top_lit ? "top-lit" : "side-lit", p.points,
                  p.DF_average_percent, p.DF_min_percent, p.uniformity,
                  p.achieved ? daylight::to_string(*p.achieved) : "none");
    out += line;
    for (const auto& l : p.levels) {
      for (const auto* c : {&l.target, &l.minimum_target}) {
        std::snprintf(line, sizeof line,
                      "    %-8s %4g lx  DF >= %5.2f %%  over %3g %% required, %5.1f %% reached  "
                      "%s\n",
                      c == &l.target ? daylight::to_string(l.level) : "", c->illuminance_lx,
                      c->daylight_factor_percent, 100.0 * c->required_fraction, 100.0 * c->fraction,
                      c->met ? "met" : "NOT MET");
        out += line;
      }
    }
  }
  return out;
}

}  // namespace luxgrid::report
