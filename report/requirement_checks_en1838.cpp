#include "report/requirement_checks_en1838.h"

#include "util/error.h"

namespace luxgrid::report {

namespace {

const calc::SurfaceResult& result_named(const calc::Results& results, const std::string& name) {
  for (const auto& s : results.surfaces) {
    if (s.grid.name == name) return s;
  }
  throw InputError("EN 1838 checks: no calculation surface named \"" + name + "\"");
}

// One check: a lower limit on Emin, or the upper limit of Emax / Emin.
RequirementCheck make_check(const calc::SurfaceResult& s, calc::EmergencyRole role,
                            const char* quantity, double required, const char* clause) {
  RequirementCheck c;
  c.surface = s.grid.name;
  c.role = calc::to_string(role);
  c.quantity = quantity;
  c.required = required;
  c.source = std::string("EN 1838:2013 clause ") + clause;
  c.fixed_by_standard = true;
  const bool diversity = c.quantity == kDiversityQuantity;
  c.upper_limit = diversity;
  if (diversity) {
    if (!(s.stats.Emin > 0.0)) {
      c.calculated = false;
      c.note = "Emin is 0 lx, so Emax / Emin is unbounded";
      return c;
    }
    c.achieved = s.stats.Emax / s.stats.Emin;
    c.margin = required - c.achieved;
  } else {
    c.achieved = s.stats.Emin;
    c.margin = c.achieved - required;
  }
  c.margin_rel = c.margin / required;
  c.met = c.margin >= -kAtLimitRelTol * required;
  return c;
}

}  // namespace

std::vector<RequirementCheck> check_en1838(const calc::Results& results,
                                           const std::vector<calc::EmergencySurface>& surfaces) {
  using calc::EmergencyRole;
  std::vector<RequirementCheck> checks;
  for (const auto& e : surfaces) {
    const calc::SurfaceResult& s = result_named(results, e.grid);
    switch (e.role) {
      case EmergencyRole::route_centre_line:
        checks.push_back(make_check(s, e.role, "Emin", calc::kRouteCentreLineEmin_lx, "4.2"));
        checks.push_back(make_check(s, e.role, kDiversityQuantity, calc::kMaxDiversity, "4.2"));
        break;
      case EmergencyRole::route_band:
        checks.push_back(make_check(s, e.role, "Emin", calc::kRouteBandEmin_lx, "4.2"));
        break;
      case EmergencyRole::open_area:
        checks.push_back(make_check(s, e.role, "Emin", calc::kOpenAreaEmin_lx, "4.3"));
        checks.push_back(make_check(s, e.role, kDiversityQuantity, calc::kMaxDiversity, "4.3"));
        break;
    }
  }
  return checks;
}

}  // namespace luxgrid::report
