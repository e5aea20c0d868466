// The project's "photometry" entries: built-in distributions and files, scaled.
#include "project/project_parts.h"

#include <algorithm>
#include <memory>

#include "calc/scaled_distribution.h"
#include "photometry/builtin.h"
#include "photometry/tabular_distribution.h"
#include "util/file_kind.h"
#include "util/paths.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

photometry::Photometry parse_builtin(const JsonValue& e) {
  e.expect_object();
  const auto kind = e.at("builtin");
  const auto i0_v = e.at("intensity_cd");
  const double i0 = i0_v.as_non_negative();
  if (i0 > kMaxIntensity_cd) {
    i0_v.fail("expected at most " + number_text(kMaxIntensity_cd) +
              " cd (the intensity limit), got " + number_text(i0));
  }
  photometry::Photometry p;
  p.format = "builtin";
  const std::string name = kind.as_string();
  if (name == "isotropic") {
    p.distribution = std::make_shared<photometry::IsotropicDistribution>(i0);
  } else if (name == "lambertian") {
    p.distribution = std::make_shared<photometry::LambertianDistribution>(i0);
  } else {
    kind.fail("expected \"isotropic\" or \"lambertian\", got \"" + name + "\"");
  }
  p.source = "builtin:" + name;
  return p;
}

photometry::Photometry load_file_entry(const JsonValue& where, const std::string& relative,
                                       const FilePolicy& policy) {
  const std::filesystem::path path = policy.base_dir / relative;
  const std::filesystem::path root = policy.base_dir.empty() ? "." : policy.base_dir;
  // Checked before looking at the file, so a refused path tells nothing about what exists there.
  if (!policy.allow_outside && !lies_within(path, root)) {
    where.fail("the photometry file " + relative +
               " lies outside the project folder; to allow it, set \"settings\": "
               "{\"allow_files_outside_project\": true}");
  }
  // By stat, before any open (util/file_kind.h): a FIFO would block the open. The file is named
  // as the project names it, wherever luxgrid was started.
  if (const std::string what = not_a_regular_file(path); !what.empty()) {
    where.fail(what == "file not found" ? "photometry file not found: " + relative
                                        : "the photometry file " + relative + " " + what);
  }
  // TILT=<file> obeys the same rule, inside the photometry reader.
  photometry::LoadOptions options;
  if (!policy.allow_outside) options.allowed_root = root;
  options.name = relative;
  // The reader's message names the photometric file and line; put the project's place first.
  auto p = at_place(where, [&] { return photometry::load_photometry_file(path, options); });
  p.source = relative;
  return p;
}

// The brightest direction of a distribution as loaded, cd: the largest table value (the
// interpolants stay within their neighbours' range up to bicubic overshoot, far below the
// limit's margin), or a 1-degree scan for anything without a table.
double peak_intensity_cd(const photometry::Photometry& p) {
  if (p.table) {
    const auto& cd = p.table->grid().cd;
    return cd.empty() ? 0.0 : *std::max_element(cd.begin(), cd.end());
  }
  double peak = 0.0;
  for (int g = 0; g <= 180; ++g) {
    for (int c = 0; c < 360; ++c) {
      peak = std::max(
          peak, p.distribution->intensity(photometry::direction_of(c * kDegToRad, g * kDegToRad)));
    }
  }
  return peak;
}

// The scaled peak must stay finite, below kMaxIntensity_cd (util/limits.h) and, for a file that
// emits light, above kMinScaledIntensity_cd.
void check_peak(const JsonValue& where, double peak_cd, double factor) {
  const double scaled = peak_cd * factor;
  const std::string would = "the peak intensity would be " + number_text(scaled) + " cd (" +
                            number_text(peak_cd) + " cd x " + number_text(factor) + "), ";
  if (!(scaled <= kMaxIntensity_cd)) {
    where.fail(would + "more than the limit of " + number_text(kMaxIntensity_cd) + " cd");
  }
  if (peak_cd > 0.0 && scaled < kMinScaledIntensity_cd) {
    where.fail(would + "less than the limit of " + number_text(kMinScaledIntensity_cd) + " cd");
  }
}

photometry::Photometry parse_photometry_entry(const JsonValue& e, const FilePolicy& policy) {
  if (e.is_string()) return load_file_entry(e, e.as_string(), policy);
  if (!e.is_object()) e.fail("expected a file path or an object, got " + json_type_name(e.raw()));
  if (e.has("builtin")) return parse_builtin(e);
  e.expect_object();
  const auto file = e.at("file");
  auto p = load_file_entry(file, file.as_string(), policy);
  const double peak_cd = peak_intensity_cd(p);
  double factor = 1.0;  // everything applied so far
  if (auto m = e.find("multiplier")) {
    factor = m->as_positive();
    check_peak(*m, peak_cd, factor);
    p.distribution = std::make_shared<ScaledDistribution>(p.distribution, factor);
  }
  if (auto f = e.find("flux_lm")) {
    const double target = f->as_positive();
    const double have = luminous_flux(*p.distribution);
    if (!(have > 0.0)) f->fail("cannot rescale to flux_lm: the distribution emits no light");
    check_peak(*f, peak_cd, factor * (target / have));
    p.distribution = std::make_shared<ScaledDistribution>(p.distribution, target / have);
  }
  return p;
}

}  // namespace luxgrid::project::parts
