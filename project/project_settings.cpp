// The project's "settings" (docs/project-format.md): quality, models, maintenance, scene.
#include "project/project_parts.h"

#include <utility>

#include "calc/near_model_name.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

// settings.maintenance: a number (the maintenance factor) or its parts [CIE97]
// {"LLMF", "LSF", "LMF", "RSMF"}, each in (0, 1], whose product is the factor.
void parse_maintenance(const JsonValue& m, Settings& out) {
  if (m.is_number()) {
    out.maintenance_factor = m.as_number_in(kMinMaintenanceFactor, 1.0);
    return;
  }
  if (!m.is_object()) {
    m.fail("expected a maintenance factor in [" + number_text(kMinMaintenanceFactor) +
           ", 1] or its parts {\"LLMF\", \"LSF\", \"LMF\", \"RSMF\"}, got " +
           json_type_name(m.raw()));
  }
  // CIE 97's table form (factors looked up by lamp type, luminaire category, environment and
  // cleaning interval) needs the standard's tables, which luxgrid does not ship: refuse its keys
  // with that reason rather than as unknown keys.
  for (const char* key :
       {"lamp_type", "luminaire_category", "category", "environment", "cleaning_interval",
        "cleaning_interval_years", "burning_hours", "room_index"}) {
    if (m.has(key)) {
      m.at(key).fail(
          "the CIE 97 table form of the maintenance factor is not built: luxgrid does not ship "
          "CIE 97:2005's tables of LLMF, LSF, LMF and RSMF; read the four factors from the "
          "standard or the manufacturer's data and give them as {\"LLMF\", \"LSF\", \"LMF\", "
          "\"RSMF\"}");
    }
  }
  m.expect_object();
  MaintenanceFactors f;
  const std::pair<const char*, double*> parts[] = {
      {"LLMF", &f.LLMF}, {"LSF", &f.LSF}, {"LMF", &f.LMF}, {"RSMF", &f.RSMF}};
  for (const auto& [key, value] : parts) {
    const auto v = m.at(key);  // all four: a forgotten factor would silently count as 1
    *value = v.as_number_in(0.0, 1.0);
    if (!(*value > 0.0)) v.fail("expected a factor in (0, 1], got 0");
  }
  const double mf = f.product();
  if (mf < kMinMaintenanceFactor) {
    m.fail("the maintenance factor LLMF x LSF x LMF x RSMF = " + number_text(mf) +
           " is below the limit of " + number_text(kMinMaintenanceFactor));
  }
  out.maintenance_factor = mf;
  out.maintenance_parts = f;
}

Settings parse_settings(const JsonValue& s) {
  s.expect_object();
  Settings out;
  if (auto q = s.find("quality")) {
    const auto parsed = quality_from_string(q->as_string());
    if (!parsed)
      q->fail("expected \"draft\", \"standard\", \"high\" or \"reference\", got \"" +
              q->as_string() + "\"");
    out.quality = *parsed;
  }
  if (auto n = s.find("near_field")) {
    const std::string v = n->as_string();
    if (v == "auto")
      out.near_field = NearFieldMode::automatic;
    else if (v == "always")
      out.near_field = NearFieldMode::always;
    else if (v == "never")
      out.near_field = NearFieldMode::never;
    else
      n->fail("expected \"auto\", \"always\" or \"never\", got \"" + v + "\"");
  }
  if (auto m = s.find("near_field_model")) {
    out.near_field_model = m->as_string();
    if (!near_model_named(out.near_field_model)) {
      m->fail("unknown model \"" + out.near_field_model + "\" (expected " + kNearFieldModelNames +
              ")");
    }
  }
  if (auto i = s.find("indirect")) {
    const std::string v = i->as_string();
    if (v == "auto")
      out.indirect = IndirectMode::automatic;
    else if (v == "off")
      out.indirect = IndirectMode::off;
    else if (v == "on")
      out.indirect = IndirectMode::on;
    else
      i->fail("expected \"auto\", \"off\" or \"on\", got \"" + v + "\"");
  }
  if (auto b = s.find("bounces")) {
    const std::string expected =
        "expected \"auto\" or a whole number from 1 to " + std::to_string(kMaxBounces);
    if (b->is_string()) {
      if (b->as_string() != "auto") b->fail(expected);
      out.bounces = 0;
    } else {
      // Range first, in double: as_int would take 1e9, which then hangs the iteration.
      const double n = b->as_number();
      if (!(n >= 1.0 && n <= kMaxBounces)) b->fail(expected + ", got " + b->raw().dump());
      out.bounces = b->as_int();
    }
  }
  if (auto m = s.find("maintenance_factor")) {
    out.maintenance_factor = m->as_number_in(kMinMaintenanceFactor, 1.0);
  }
  if (auto m = s.find("maintenance")) {
    if (s.has("maintenance_factor")) {
      m->fail("give either \"maintenance\" or \"maintenance_factor\", not both");
    }
    parse_maintenance(*m, out);
  }
  if (auto a = s.find("allow_files_outside_project"))
    out.allow_files_outside_project = a->as_bool();
  if (auto sc = s.find("scene")) {
    const std::string v = sc->as_string();
    if (v == "normal")
      out.scene = LightingScene::normal;
    else if (v == "emergency")
      out.scene = LightingScene::emergency;
    else if (v == "daylight")
      out.scene = LightingScene::daylight;
    else
      sc->fail("expected \"normal\", \"emergency\" or \"daylight\", got \"" + v + "\"");
  }
  return out;
}

}  // namespace luxgrid::project::parts
