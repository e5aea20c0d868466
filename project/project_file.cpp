#include "project/project_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "calc/emergency_surfaces.h"
#include "calc/luminaire_tilt.h"
#include "calc/near_model_name.h"
#include "calc/scaled_distribution.h"
#include "calc/visibility.h"
#include "geometry/workplane.h"
#include "photometry/builtin.h"
#include "photometry/tabular_distribution.h"
#include "project/json_reader.h"
#include "project/project_limits.h"
#include "project/requirements.h"
#include "project/safe_json.h"
#include "project/sanity_checks.h"
#include "util/error.h"
#include "util/output_names.h"
#include "util/paths.h"
#include "util/sha256.h"

namespace luxgrid::project {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

namespace {

// Grids moved into a vector: a braced list would copy them (its elements are const), and a
// grid of a million points is 60 MB.
template <class... Grid>
std::vector<geometry::SurfaceGrid> grids_of(Grid&&... grid) {
  std::vector<geometry::SurfaceGrid> out;
  out.reserve(sizeof...(grid));
  (out.push_back(std::forward<Grid>(grid)), ...);
  return out;
}

// A count computed in double (a 1e-300 m spacing gives 1e300 points per side): exact below
// 1e15, then in exponent form; never converted to an integer type, where it would overflow.
std::string count_text(double n) {
  if (!std::isfinite(n)) return "over 1e308";
  if (n >= 1e15) return number_text(n);
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", n);
  return buf;
}

// Coordinates and lengths in metres, within kMaxCoordinate_m of the origin.
double coordinate(const JsonValue& v) {
  const double x = v.as_number();
  if (std::abs(x) > kMaxCoordinate_m) {
    v.fail(number_text(x) + " m is beyond the limit of " + number_text(kMaxCoordinate_m) +
           " m for coordinates and lengths");
  }
  return x;
}

// An array or object of at most `limit` entries, checked before any entry is read.
void check_count(const JsonValue& v, std::size_t limit, const char* what) {
  if ((v.is_array() || v.is_object()) && v.raw().size() > limit) {
    v.fail(std::to_string(v.raw().size()) + " " + what + ", more than the limit of " +
           std::to_string(limit));
  }
}

Vec3 point3(const JsonValue& v) {
  v.as_numbers(3);  // the count and types, with their own messages
  return {coordinate(v.item(0)), coordinate(v.item(1)), coordinate(v.item(2))};
}

Vec2 point2(const JsonValue& v) {
  v.as_numbers(2);
  return {coordinate(v.item(0)), coordinate(v.item(1))};
}

double positive_length(const JsonValue& v) {
  v.as_positive();
  return coordinate(v);
}

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
    else
      sc->fail("expected \"normal\" or \"emergency\", got \"" + v + "\"");
  }
  return out;
}

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

// Where photometry files may come from: the project file's folder tree, unless the project
// says otherwise (settings.allow_files_outside_project).
struct FilePolicy {
  std::filesystem::path base_dir;  // relative paths start here
  bool allow_outside = false;
};

// Geometry checks throw InputError("room \"L\": ..."), the photometry readers
// InputError("panel.ies:14: ..."); re-throw them at the JSON value they concern, so the message
// names both the place in the project and the object or file.
template <class F>
auto at_place(const JsonValue& where, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const InputError& e) {
    where.fail(e.what());
  }
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
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    where.fail("photometry file not found: " + path.string());
  }
  // TILT=<file> obeys the same rule, inside the photometry reader.
  photometry::LoadOptions options;
  if (!policy.allow_outside) options.allowed_root = root;
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

// An emitter's side or diameter, m, within [kMinEmitterSize_m, kMaxEmitterSize_m].
void check_emitter_size(const JsonValue& where, double size_m) {
  if (size_m < kMinEmitterSize_m || size_m > kMaxEmitterSize_m) {
    where.fail("expected an emitter size from " + number_text(kMinEmitterSize_m) + " to " +
               number_text(kMaxEmitterSize_m) + " m, got " + number_text(size_m) +
               " m (a smaller source is a \"point\")");
  }
}

photometry::LuminousOpening parse_emitter(const JsonValue& e) {
  e.expect_object();
  const auto shape = e.at("shape");
  const std::string s = shape.as_string();
  photometry::LuminousOpening o;
  if (s == "rectangle") {
    if (e.has("diameter")) e.at("diameter").fail("a rectangle takes \"size\", not \"diameter\"");
    const auto size = e.at("size");
    const auto v = size.as_numbers(2);
    if (!(v[0] > 0.0 && v[1] > 0.0)) size.fail("expected two positive sizes in metres");
    check_emitter_size(size.item(0), v[0]);
    check_emitter_size(size.item(1), v[1]);
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = v[0];
    o.width = v[1];
  } else if (s == "disk") {
    if (e.has("size")) e.at("size").fail("a disk takes \"diameter\", not \"size\"");
    o.shape = photometry::LuminousOpening::Shape::disk;
    const auto diameter = e.at("diameter");
    o.length = o.width = diameter.as_positive();
    check_emitter_size(diameter, o.length);
  } else if (s == "point") {
    if (e.has("size") || e.has("diameter")) e.fail("a point emitter has no size");
    o.shape = photometry::LuminousOpening::Shape::point;
  } else {
    shape.fail("expected \"rectangle\", \"disk\" or \"point\", got \"" + s + "\"");
  }
  return o;
}

// A luminaire's "emergency" entry [EN1838]: {"fraction": f} of its output (0 < f <= 1),
// {"flux_lm": F} (its own distribution scaled to F lumens, at most its normal flux) or
// {"photometry": "key"} (a separate photometry entry, e.g. the emergency module's own file).
EmergencyOutput parse_emergency_output(const JsonValue& e, const Scene& scene,
                                       const photometry::Photometry& own) {
  if (!e.is_object())
    e.fail("expected {\"fraction\": f}, {\"flux_lm\": F} or {\"photometry\": \"key\"}, got " +
           json_type_name(e.raw()));
  e.expect_object();
  if (e.raw().size() != 1)
    e.fail("expected exactly one of \"fraction\", \"flux_lm\" or \"photometry\"");
  EmergencyOutput out;
  if (auto f = e.find("fraction")) {
    out.factor = f->as_number_in(0.0, 1.0);
    if (!(out.factor > 0.0)) f->fail("expected a fraction in (0, 1], got 0");
    out.description = number_text(out.factor) + " of its output";
  } else if (auto fl = e.find("flux_lm")) {
    const double target = fl->as_positive();
    const double have = luminous_flux(*own.distribution);
    if (!(have > 0.0))
      fl->fail("cannot scale to flux_lm: the luminaire's distribution emits no light");
    if (target > have) {
      fl->fail("the emergency flux " + number_text(target) +
               " lm is more than the luminaire's own " + number_text(have) +
               " lm; for a separate emergency distribution give {\"photometry\": \"key\"}");
    }
    out.factor = target / have;
    out.description = number_text(target) + " lm";
  } else {
    const auto p = e.at("photometry");
    out.photometry = p.as_string();
    if (!scene.photometry.count(out.photometry))
      p.fail("no photometry entry named \"" + out.photometry + "\"");
    out.description = "photometry \"" + out.photometry + "\"";
  }
  return out;
}

geometry::Obstacle parse_obstacle(const JsonValue& o, size_t index, const Room& room,
                                  std::vector<std::string>& warnings) {
  o.expect_object();
  const std::string name =
      o.has("name") ? o.at("name").as_string() : "obstacle " + std::to_string(index);
  // Furniture and columns: mid-grey unless given, like the room's walls.
  constexpr double kDefaultObstacleReflectance = 0.5;
  const double rho = o.has("reflectance") ? o.at("reflectance").as_number_in(0.0, 1.0)
                                          : kDefaultObstacleReflectance;
  if (o.has("box") == o.has("prism")) o.fail("expected exactly one of \"box\" or \"prism\"");
  geometry::Obstacle out;
  if (auto b = o.find("box")) {
    b->expect_object();
    const Vec3 lo = point3(b->at("min")), hi = point3(b->at("max"));
    const double rot = b->has("rotation_z") ? b->at("rotation_z").as_number() * kDegToRad : 0.0;
    out = at_place(*b, [&] { return geometry::make_box(name, lo, hi, rot, rho); });
  } else {
    const auto p = o.at("prism");
    p.expect_object();
    const auto outline_v = p.at("outline");
    geometry::Polygon2 outline;
    check_count(outline_v, kMaxOutlineCorners, "corners");
    for (const auto& c : outline_v.items()) outline.push_back(point2(c));
    const double z0 = coordinate(p.at("z0")), z1 = coordinate(p.at("z1"));
    bool reversed = false;
    out = at_place(outline_v,
                   [&] { return geometry::make_prism(name, outline, z0, z1, rho, &reversed); });
    if (reversed) {
      warnings.push_back("obstacle \"" + name +
                         "\": the outline is clockwise; reversed to counter-clockwise");
    }
  }
  const double top = room.floor_z + room.height;
  if (!(out.z1 > room.floor_z && out.z0 < top) ||
      !geometry::polygons_overlap(out.footprint, room.outline)) {
    o.fail("obstacle \"" + name + "\" lies outside room \"" + room.name + "\"");
  }
  return out;
}

Room parse_room(const JsonValue& r, std::vector<std::string>& warnings) {
  r.expect_object();
  Room room;
  room.name = r.at("name").as_string();
  const auto outline = r.at("outline");
  check_count(outline, kMaxOutlineCorners, "corners");
  for (const auto& p : outline.items()) room.outline.push_back(point2(p));
  if (room.outline.size() < 3) {
    outline.fail("expected at least 3 corners, got " + std::to_string(room.outline.size()));
  }
  const bool reversed = at_place(outline, [&] {
    return geometry::normalize_outline(room.outline, "room \"" + room.name + "\"");
  });
  if (reversed) {
    warnings.push_back("room \"" + room.name +
                       "\": the outline is clockwise; reversed to counter-clockwise");
  }
  if (auto z = r.find("floor_z")) room.floor_z = coordinate(*z);
  const auto height_v = r.at("height");
  room.height = positive_length(height_v);
  if (room.height > kMaxRoomHeight_m) {
    // Refused before any grid or patch is sized by it: a project in millimetres would otherwise
    // calculate a room a thousand times too large (minutes, gigabytes, and 0.0003 lx).
    height_v.fail("the room \"" + room.name + "\" is " + number_text(room.height) +
                  " m high, more than the limit of " + number_text(kMaxRoomHeight_m) +
                  " m for a room; the lengths look like millimetres, and luxgrid reads metres "
                  "(divide them by 1000)");
  }
  if (auto refl = r.find("reflectance")) {
    refl->expect_object();
    if (auto f = refl->find("floor")) room.reflectance.floor = f->as_number_in(0.0, 1.0);
    if (auto w = refl->find("walls")) room.reflectance.walls = w->as_number_in(0.0, 1.0);
    if (auto c = refl->find("ceiling")) room.reflectance.ceiling = c->as_number_in(0.0, 1.0);
  }
  if (auto obstacles = r.find("obstacles")) {
    size_t index = 0;
    for (const auto& o : obstacles->items()) {
      room.obstacles.push_back(parse_obstacle(o, index++, room, warnings));
      for (size_t k = 0; k + 1 < room.obstacles.size(); ++k) {
        if (room.obstacles[k].name == room.obstacles.back().name) {
          o.at("name").fail("an obstacle named \"" + room.obstacles.back().name +
                            "\" already exists in room \"" + room.name + "\"");
        }
      }
    }
  }
  return room;
}

glm::dmat3 parse_rotation(const JsonValue& rot) {
  const auto v = rot.as_numbers(3);
  return rotation_xyz(v[0] * kDegToRad, v[1] * kDegToRad, v[2] * kDegToRad);
}

// The project's luminaires, arrays expanded, would number `total`.
void check_luminaire_count(const JsonValue& where, size_t total) {
  if (total > kMaxLuminaires) {
    where.fail("the project would have " + std::to_string(total) +
               " luminaires, more than the limit of " + std::to_string(kMaxLuminaires));
  }
}

void parse_luminaire(const JsonValue& l, size_t index, const Scene& scene,
                     std::vector<Luminaire>& out) {
  l.expect_object();
  const auto ph = l.at("photometry");
  const std::string key = ph.as_string();
  const auto it = scene.photometry.find(key);
  if (it == scene.photometry.end()) ph.fail("no photometry entry named \"" + key + "\"");

  Luminaire base;
  base.label = l.has("name") ? l.at("name").as_string() : "luminaire " + std::to_string(index);
  base.photometry = key;
  base.distribution = it->second.distribution;
  base.opening = it->second.opening;
  if (auto e = l.find("emitter")) base.opening = parse_emitter(*e);
  if (auto e = l.find("emergency")) base.emergency = parse_emergency_output(*e, scene, it->second);
  if (auto r = l.find("rotation")) base.pose.rotation = parse_rotation(*r);

  const bool has_position = l.has("position");
  const bool has_array = l.has("array");
  if (has_position == has_array) l.fail("expected exactly one of \"position\" or \"array\"");
  if (has_position) {
    base.pose.position = point3(l.at("position"));
    check_luminaire_count(l, out.size() + 1);
    out.push_back(base);
    return;
  }
  const auto a = l.at("array");
  a.expect_object();
  const Vec3 origin = point3(a.at("origin"));
  const auto count_v = a.at("count");
  count_v.as_numbers(2);
  int n[2];
  for (int k = 0; k < 2; ++k) {
    const auto c = count_v.item(k);
    // In double first: as_int refuses only beyond 1e9, and the product could overflow an int.
    const double x = c.as_number();
    if (!(x >= 1.0 && x <= kMaxArrayCount)) {
      c.fail("expected a count from 1 to " + std::to_string(kMaxArrayCount));
    }
    n[k] = c.as_int();
  }
  // Counted before a single copy is made (10 000 x 10 000 copies took 2.2 GB, then bad_alloc).
  const double members = static_cast<double>(n[0]) * n[1];
  if (members > static_cast<double>(kMaxLuminaires)) {
    count_v.fail("the array has " + count_text(members) + " luminaires, more than the limit of " +
                 std::to_string(kMaxLuminaires) + " in a project");
  }
  check_luminaire_count(count_v, out.size() + static_cast<size_t>(members));
  const auto spacing_v = a.at("spacing");
  const Vec2 spacing = point2(spacing_v);
  // The far corner, too, must lie within the coordinate limit.
  const Vec3 last = origin + Vec3(spacing.x * (n[0] - 1), spacing.y * (n[1] - 1), 0.0);
  for (int k = 0; k < 2; ++k) {
    if (std::abs(last[k]) > kMaxCoordinate_m) {
      spacing_v.fail("the array reaches " + std::string(k == 0 ? "x" : "y") + " = " +
                     number_text(last[k]) + " m, beyond the limit of " +
                     number_text(kMaxCoordinate_m) + " m for coordinates");
    }
  }
  for (int j = 0; j < n[1]; ++j) {
    for (int i = 0; i < n[0]; ++i) {
      Luminaire lum = base;
      lum.pose.position = origin + Vec3(spacing.x * i, spacing.y * j, 0.0);
      lum.label = base.label + " [" + std::to_string(i) + "," + std::to_string(j) + "]";
      out.push_back(lum);
    }
  }
}

double parse_spacing(const JsonValue& s, const std::optional<JsonValue>& spacing,
                     double longer_side) {
  if (!spacing) s.fail("missing required key \"spacing\" (metres or \"auto\")");
  if (spacing->is_string()) {
    if (spacing->as_string() != "auto") spacing->fail("expected a number of metres or \"auto\"");
    return geometry::auto_spacing(longer_side);
  }
  return spacing->as_positive();
}

// Grid points promised so far over all surfaces. Each surface is charged its point count,
// computed in double, before its grid is built: nothing is allocated for a refused grid. The
// luminaire-point pairs (the direct calculation's work) are charged at the same time.
class GridBudget {
 public:
  explicit GridBudget(size_t luminaires) : luminaires_(static_cast<double>(luminaires)) {}
  void spend(const JsonValue& where, double points, const char* grids = "grid") {
    if (!(points <= kMaxGridPoints)) {
      where.fail(std::string("the ") + grids + " would have " + count_text(points) +
                 " points, more than the limit of " + count_text(kMaxGridPoints) +
                 "; use a larger spacing");
    }
    if (used_ + points > kMaxTotalGridPoints) {
      where.fail("the surfaces would have " + count_text(used_ + points) +
                 " points together, more than the limit of " + count_text(kMaxTotalGridPoints) +
                 "; use larger spacings or fewer surfaces");
    }
    used_ += points;
    const double pairs = luminaires_ * used_;
    if (pairs > kMaxLuminairePointPairs) {
      where.fail(
          number_text(luminaires_) + " luminaires x " + count_text(used_) +
          " points = " + number_text(pairs) + " luminaire-point pairs, more than the limit of " +
          number_text(kMaxLuminairePointPairs) + "; use fewer luminaires or larger spacings");
    }
  }
  // Views of observers surfaces: each lists a glare term per luminaire (kMaxViewLuminairePairs).
  void spend_views(const JsonValue& where, double views) {
    views_ += views;
    const double pairs = luminaires_ * views_;
    if (pairs > kMaxViewLuminairePairs) {
      where.fail(number_text(luminaires_) + " luminaires x " + count_text(views_) + " views = " +
                 number_text(pairs) + " view-luminaire pairs, more than the limit of " +
                 number_text(kMaxViewLuminairePairs) +
                 " for observers surfaces; use fewer views or observers");
    }
  }
  void spend_cells(const JsonValue& where, double size_u, double size_v, double spacing) {
    spend(where, std::ceil(size_u / spacing) * std::ceil(size_v / spacing));
  }

 private:
  double luminaires_;
  double used_ = 0.0;
  double views_ = 0.0;
};

const Room& find_room(const JsonValue& where, const Scene& scene, const std::string& name) {
  for (const auto& r : scene.rooms) {
    if (r.name == name) return r;
  }
  where.fail("no room named \"" + name + "\"");
}

size_t active_points(const geometry::SurfaceGrid& g) {
  size_t n = 0;
  for (bool a : g.active) n += a;
  return n;
}

// "quantity" and "facing": what the numbers of a surface mean (geometry::Quantity). Horizontal
// and vertical replace the receiver normals; cylindrical keeps them (the calculation ignores
// them for E_cyl); semi-cylindrical sets them to the horizontal direction the half cylinder faces,
// found like a vertical plane's normal.
void apply_quantity(const JsonValue& s, std::vector<geometry::SurfaceGrid>& grids) {
  const auto q = s.find("quantity");
  const auto facing = s.find("facing");
  geometry::Quantity quantity = geometry::Quantity::planar;
  if (q) {
    const std::string v = q->as_string();
    if (v == "planar")
      quantity = geometry::Quantity::planar;
    else if (v == "horizontal")
      quantity = geometry::Quantity::horizontal;
    else if (v == "vertical")
      quantity = geometry::Quantity::vertical;
    else if (v == "cylindrical")
      quantity = geometry::Quantity::cylindrical;
    else if (v == "semi-cylindrical")
      quantity = geometry::Quantity::semi_cylindrical;
    else
      q->fail(
          "expected \"planar\", \"horizontal\", \"vertical\", \"cylindrical\" or "
          "\"semi-cylindrical\", got \"" +
          v + "\"");
  }
  // Both turn the receiver towards a horizontal direction: a vertical plane, a half cylinder.
  const bool faces =
      quantity == geometry::Quantity::vertical || quantity == geometry::Quantity::semi_cylindrical;
  if (facing && !faces) {
    facing->fail("\"facing\" only goes with \"quantity\": \"vertical\" or \"semi-cylindrical\"");
  }
  std::optional<Vec3> facing_dir;
  if (facing) {
    const Vec2 f = facing->as_vec2();
    if (glm::length(f) == 0.0) facing->fail("expected a non-zero horizontal direction");
    facing_dir = glm::normalize(Vec3(f.x, f.y, 0.0));
  }
  // A surface normal closer to vertical than this has no usable horizontal direction.
  constexpr double kMinHorizontalPart = 1e-9;
  for (auto& g : grids) {
    g.quantity = quantity;
    for (auto& n : g.normals) {
      if (quantity == geometry::Quantity::horizontal) {
        n = Vec3(0, 0, 1);
      } else if (faces) {
        if (facing_dir) {
          n = *facing_dir;
        } else {
          const Vec3 h(n.x, n.y, 0.0);
          if (!(glm::length(h) > kMinHorizontalPart)) {
            q->fail("a " +
                    std::string(quantity == geometry::Quantity::vertical ? "vertical"
                                                                         : "semi-cylindrical") +
                    " quantity on a horizontal surface needs \"facing\": [x, y]");
          }
          n = glm::normalize(h);
        }
      }
    }
  }
}

// A unit view direction: non-zero and not vertical (kMinViewHorizontalPart).
Vec3 view_direction(const JsonValue& v) {
  const Vec3 d = point3(v);
  if (glm::length(d) == 0.0) v.fail("expected a non-zero direction");
  const Vec3 n = glm::normalize(d);
  if (!(std::hypot(n.x, n.y) >= kMinViewHorizontalPart)) {
    v.fail(
        "a view direction must not be vertical (the position index measures heights above the "
        "line of sight in the vertical plane through it)");
  }
  return n;
}

// "observers": [{"at": [x, y, z], "directions": [[dx, dy, dz], ...] or N}]: one point per
// (observer, view), its normal the view direction (geometry::SurfaceGrid::Kind::observers).
// "directions": N gives N horizontal directions from +x, counter-clockwise, evenly spaced.
geometry::SurfaceGrid parse_observers(const JsonValue& s, const JsonValue& obs,
                                      const std::string& name, GridBudget& budget) {
  for (const char* key : {"spacing", "quantity", "facing"}) {
    if (s.has(key)) s.at(key).fail(std::string("an observers surface has no \"") + key + "\"");
  }
  if (!obs.is_array()) obs.fail("expected an array of observers, got " + json_type_name(obs.raw()));
  check_count(obs, kMaxObservers, "observers");
  if (obs.raw().empty()) obs.fail("expected at least one observer");
  geometry::SurfaceGrid g;
  g.name = name;
  g.kind = geometry::SurfaceGrid::Kind::observers;
  size_t index = 0;
  for (const auto& o : obs.items()) {
    o.expect_object();
    const Vec3 at = point3(o.at("at"));
    const auto dirs = o.at("directions");
    std::vector<Vec3> views;
    if (dirs.is_number()) {
      const double n = dirs.as_number();
      if (!(n >= 1.0 && n <= static_cast<double>(kMaxViewsPerObserver)) || n != std::floor(n)) {
        dirs.fail("expected a whole number of horizontal directions from 1 to " +
                  std::to_string(kMaxViewsPerObserver) + ", got " + dirs.raw().dump());
      }
      const int count = dirs.as_int();
      for (int k = 0; k < count; ++k) {
        // cos(pi / 2) is 6e-17, not 0: snap round-off so +y is written as [0, 1, 0].
        const double a = 2.0 * kPi * k / count;
        const auto snap = [](double c) { return std::abs(c) < 1e-12 ? 0.0 : c; };
        views.emplace_back(snap(std::cos(a)), snap(std::sin(a)), 0.0);
      }
    } else {
      if (!dirs.is_array())
        dirs.fail("expected a number of directions or an array of [dx, dy, dz]");
      check_count(dirs, kMaxViewsPerObserver, "directions");
      if (dirs.raw().empty()) dirs.fail("expected at least one direction");
      for (const auto& d : dirs.items()) views.push_back(view_direction(d));
    }
    budget.spend(dirs, static_cast<double>(views.size()), "observers surface");
    budget.spend_views(dirs, static_cast<double>(views.size()));
    for (const Vec3& v : views) {
      g.points.push_back(at);
      g.normals.push_back(v);
      g.observer.push_back(index);
    }
    ++index;
  }
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  g.active.assign(g.points.size(), true);
  return g;
}

// EN 1838 surfaces (calc/emergency_surfaces.h), on the floor, horizontal illuminance:
// "escape_route": {"path": [[x, y], ...], "width": w, "floor_z": z} gives the grids
// "<name> centre line" and "<name> band"; "open_area": {"room": r, "outline": [[x, y], ...]} the
// room's floor (or the outline's, at the room's floor) without a 0.5 m border.
std::vector<geometry::SurfaceGrid> parse_emergency_surface(const JsonValue& s, const Scene& scene,
                                                           const std::string& name,
                                                           GridBudget& budget) {
  for (const char* key : {"quantity", "facing"}) {
    if (s.has(key))
      s.at(key).fail(
          std::string(
              "an EN 1838 surface measures horizontal illuminance on the floor; it has no \"") +
          key + "\"");
  }
  if (auto r = s.find("escape_route")) {
    r->expect_object();
    const auto path_v = r->at("path");
    if (!path_v.is_array())
      path_v.fail("expected an array of [x, y] corners, got " + json_type_name(path_v.raw()));
    check_count(path_v, kMaxEscapeRouteCorners, "corners");
    geometry::Polygon2 path;
    for (const auto& p : path_v.items()) {
      path.push_back(point2(p));
      // A segment shorter than 1 mm has no usable direction (its band would point anywhere).
      constexpr double kMinSegment_m = 1e-3;
      if (path.size() > 1 && glm::length(path.back() - path[path.size() - 2]) < kMinSegment_m) {
        p.fail("the corner repeats the one before it");
      }
    }
    if (path.size() < 2) path_v.fail("expected at least 2 corners (the route's centre line)");
    const auto width_v = r->at("width");
    const double width = positive_length(width_v);
    if (width > kMaxEscapeRouteWidth_m) {
      width_v.fail("EN 1838's escape-route rules hold for routes up to " +
                   number_text(kMaxEscapeRouteWidth_m) + " m wide, got " + number_text(width) +
                   " m; give a wider route as several routes of at most " +
                   number_text(kMaxEscapeRouteWidth_m) + " m, or as an open_area");
    }
    const double z = r->has("floor_z") ? coordinate(r->at("floor_z")) : 0.0;
    const double spacing = parse_spacing(s, s.find("spacing"), path_length(path));
    budget.spend(s, escape_route_point_count(path, width, spacing), "escape route");
    const EscapeRoutePoints points = escape_route_points(path, width, spacing);
    return grids_of(floor_points_grid(name + " centre line", points.centre_line, z),
                    floor_points_grid(name + " band", points.band, z));
  }
  const auto a = s.at("open_area");
  a.expect_object();
  const auto room_v = a.at("room");
  const Room& room = find_room(room_v, scene, room_v.as_string());
  geometry::Polygon2 outline = room.outline;
  if (auto o = a.find("outline")) {
    outline.clear();
    check_count(*o, kMaxOutlineCorners, "corners");
    for (const auto& p : o->items()) outline.push_back(point2(p));
    if (outline.size() < 3)
      o->fail("expected at least 3 corners, got " + std::to_string(outline.size()));
    // Either orientation: reversed to counter-clockwise quietly (the outline only bounds the grid).
    (void)at_place(
        *o, [&] { return geometry::normalize_outline(outline, "open area \"" + name + "\""); });
  }
  const auto region = geometry::inset_outline(outline, kOpenAreaBorder_m);
  if (region.empty())
    a.fail("the 0.5 m border that EN 1838 leaves out of an open area leaves no core area");
  const auto box = geometry::bounds(region);
  const double su = box.hi.x - box.lo.x, sv = box.hi.y - box.lo.y;
  const double spacing = parse_spacing(s, s.find("spacing"), std::max(su, sv));
  budget.spend_cells(s, su, sv, spacing);
  auto g = geometry::make_region_grid(name, region, room.floor_z, spacing, room.obstacles);
  g.quantity = geometry::Quantity::horizontal;
  if (active_points(g) == 0)
    s.fail(
        "no grid point lies inside the open area's core and outside obstacles; use a smaller "
        "spacing");
  return grids_of(std::move(g));
}

std::vector<geometry::SurfaceGrid> parse_surface_kind(const JsonValue& s, const Scene& scene,
                                                      const std::string& name, GridBudget& budget) {
  if (auto w = s.find("workplane")) {
    w->expect_object();
    const auto room_v = w->at("room");
    const Room& room = find_room(room_v, scene, room_v.as_string());
    const auto height_v = w->at("height");
    const double height = height_v.as_non_negative();
    if (height > room.height) height_v.fail("the workplane is above the ceiling of the room");
    const double border =
        w->has("border") ? (w->at("border").as_non_negative(), coordinate(w->at("border"))) : 0.0;
    // The outline inset by the border (straight skeleton: L-shapes and notches inset right).
    const auto region = geometry::inset_outline(room.outline, border);
    if (region.empty()) w->at("border").fail("the border leaves no workplane inside the room");
    const auto box = geometry::bounds(region);
    const double su = box.hi.x - box.lo.x, sv = box.hi.y - box.lo.y;
    const double spacing = parse_spacing(s, s.find("spacing"), std::max(su, sv));
    budget.spend_cells(s, su, sv, spacing);
    auto g =
        geometry::make_region_grid(name, region, room.floor_z + height, spacing, room.obstacles);
    if (active_points(g) == 0) {
      s.fail(
          "no grid point lies inside the workplane and outside obstacles; use a smaller spacing");
    }
    return grids_of(std::move(g));
  }
  if (auto rs = s.find("room_surfaces")) {
    rs->expect_object();
    const auto room_v = rs->at("room");
    const Room& room = find_room(room_v, scene, room_v.as_string());
    const auto spacing_v = s.find("spacing");
    if (!spacing_v) s.fail("missing required key \"spacing\" (metres or \"auto\")");
    double spacing = 0.0;  // 0: auto per face
    if (spacing_v->is_string()) {
      if (spacing_v->as_string() != "auto")
        spacing_v->fail("expected a number of metres or \"auto\"");
    } else {
      spacing = spacing_v->as_positive();
    }
    // Budget over all faces at the finest spacing any face gets (auto: the smaller of the
    // floor's and the shortest face side's rule; a wall's grid is at least one cell long).
    const auto shape = room_shape(room);
    const auto box = geometry::bounds({room.outline});
    double wall_length = 0.0;
    for (size_t k = 0; k < room.outline.size(); ++k) {
      wall_length += glm::length(room.outline[(k + 1) % room.outline.size()] - room.outline[k]);
    }
    const double p = spacing > 0.0 ? spacing
                                   : std::min(geometry::auto_spacing(box.longer_side()),
                                              geometry::auto_spacing(room.height));
    const double points =
        2.0 * std::ceil((box.hi.x - box.lo.x) / p) * std::ceil((box.hi.y - box.lo.y) / p) +
        std::ceil(wall_length / p + static_cast<double>(room.outline.size())) *
            std::ceil(room.height / p);
    budget.spend(s, points, "grids");
    return geometry::make_room_surface_grids(name, shape, spacing, room.obstacles);
  }
  if (auto p = s.find("plane")) {
    p->expect_object();
    const Vec3 origin = point3(p->at("origin"));
    const auto u_v = p->at("u"), v_v = p->at("v");
    const Vec3 u = point3(u_v), v = point3(v_v);
    if (glm::length(u) == 0.0) u_v.fail("expected a non-zero direction");
    if (glm::length(v) == 0.0) v_v.fail("expected a non-zero direction");
    const Vec3 un = glm::normalize(u), vn = glm::normalize(v);
    if (std::abs(glm::dot(un, vn)) > 1e-9) v_v.fail("u and v must be perpendicular");
    const auto size_v = p->at("size");
    const Vec2 size = point2(size_v);
    if (!(size.x > 0.0 && size.y > 0.0)) size_v.fail("expected two positive sizes in metres");
    const double spacing = parse_spacing(s, s.find("spacing"), std::max(size.x, size.y));
    budget.spend_cells(s, size.x, size.y, spacing);
    return grids_of(geometry::make_plane_grid(name, origin, un, vn, size.x, size.y, spacing));
  }
  if (auto obs = s.find("observers")) return grids_of(parse_observers(s, *obs, name, budget));
  if (s.has("escape_route") || s.has("open_area"))
    return parse_emergency_surface(s, scene, name, budget);
  const auto pts = s.at("points");
  if (s.has("spacing")) s.at("spacing").fail("a points surface has no spacing");
  if (pts.is_array()) budget.spend(pts, static_cast<double>(pts.raw().size()), "points surface");
  geometry::SurfaceGrid g;
  g.name = name;
  g.kind = geometry::SurfaceGrid::Kind::points;
  for (const auto& p : pts.items()) {
    p.expect_object();
    g.points.push_back(point3(p.at("at")));
    const auto nv = p.at("normal");
    const Vec3 n = point3(nv);
    if (glm::length(n) == 0.0) nv.fail("expected a non-zero normal");
    g.normals.push_back(glm::normalize(n));
  }
  if (g.points.empty()) pts.fail("expected at least one point");
  g.nu = static_cast<int>(g.points.size());
  g.nv = 1;
  g.active.assign(g.points.size(), true);
  return grids_of(std::move(g));
}

// One surface entry gives one grid, or several for room_surfaces ("<name> floor", ...).
// A surface's name becomes its output file names; kMaxSurfaceNameLength keeps them short enough.
void check_name_length(const JsonValue& where, const std::string& name) {
  if (name.empty())
    where.fail("expected a surface name, got an empty one (it names the surface's output files)");
  if (name.size() > kMaxSurfaceNameLength) {
    where.fail("the surface name is " + std::to_string(name.size()) +
               " characters long, more than the limit of " + std::to_string(kMaxSurfaceNameLength) +
               " (it names the surface's output files)");
  }
}

// The output files claimed so far (util/output_names.h), compared ignoring case: on a
// case-insensitive file system A.csv and a.csv are one file, and one surface's results would
// silently replace another's.
class OutputNames {
 public:
  void claim(const JsonValue& where, const std::string& surface) {
    const SurfaceOutputFiles files = surface_output_files(surface);
    for (const std::string* file : files.all()) {
      std::string key = *file;
      for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (key.front() == '.') {
        where.fail("surface \"" + surface + "\" would write the hidden file " + *file +
                   "; start its name with a letter or digit");
      }
      for (const char* reserved : kFolderOutputFiles) {
        if (key == reserved) {
          where.fail("surface \"" + surface + "\" would write " + *file +
                     ", which the output folder uses for itself; rename the surface");
        }
      }
      const auto [it, fresh] = owner_.emplace(key, surface);
      if (!fresh) {
        where.fail("surface \"" + surface + "\" would write " + *file + ", which surface \"" +
                   it->second +
                   "\" also writes (output file names ignore case and turn characters " +
                   "other than letters, digits, '-', '_' and '.' into '_'); rename one of them");
      }
    }
  }

 private:
  std::map<std::string, std::string> owner_;  // lower-case file name -> surface name
};

std::vector<geometry::SurfaceGrid> parse_surface(const JsonValue& s, const Scene& scene,
                                                 GridBudget& budget) {
  // "requirements" (EN 12464-1 checks) is read by parse_project into Project::requirements.
  s.expect_object();
  const std::string name = s.at("name").as_string();
  check_name_length(s.at("name"), name);
  const int kinds = s.has("workplane") + s.has("plane") + s.has("points") + s.has("room_surfaces") +
                    s.has("observers") + s.has("escape_route") + s.has("open_area");
  if (kinds != 1 && (s.has("escape_route") || s.has("open_area"))) {
    s.fail(
        "expected exactly one of \"workplane\", \"plane\", \"points\", \"room_surfaces\", "
        "\"observers\", "
        "\"escape_route\" or \"open_area\"");
  }
  if (kinds != 1) {
    if (s.has("room_surfaces")) {
      s.fail("expected exactly one of \"workplane\", \"plane\", \"points\" or \"room_surfaces\"");
    }
    if (s.has("observers")) {
      s.fail("expected exactly one of \"workplane\", \"plane\", \"points\" or \"observers\"");
    }
    s.fail("expected exactly one of \"workplane\", \"plane\" or \"points\"");
  }
  auto grids = parse_surface_kind(s, scene, name, budget);
  if (!s.has("escape_route") && !s.has("open_area")) apply_quantity(s, grids);
  return grids;
}

// The EN 1838 role of each grid an escape_route or open_area entry gave (in
// parse_emergency_surface's order).
void record_emergency_surfaces(const JsonValue& s, const std::vector<geometry::SurfaceGrid>& grids,
                               std::vector<EmergencySurface>& out) {
  const std::string entry = s.at("name").as_string();
  if (s.has("escape_route")) {
    out.push_back({grids.at(0).name, entry, EmergencyRole::route_centre_line});
    out.push_back({grids.at(1).name, entry, EmergencyRole::route_band});
  } else if (s.has("open_area")) {
    out.push_back({grids.at(0).name, entry, EmergencyRole::open_area});
  }
}

// UGR (calc/glare) divides by the background luminance from reflected light and by each
// luminaire's projected luminous area: an observers surface refuses a project that turns
// reflections off or has a luminaire without a luminous area (a point emitter).
void check_observers_inputs(const JsonValue& s, const Scene& scene) {
  if (!s.has("observers")) return;
  if (scene.settings.indirect == IndirectMode::off) {
    s.fail(
        "an observers surface needs reflected light: UGR's background luminance is the indirect "
        "illuminance at the eye over pi (CIE 117), and \"settings\": {\"indirect\": \"off\"} "
        "leaves it 0; set \"indirect\" to \"auto\" or \"on\"");
  }
  for (const auto& l : scene.luminaires) {
    if (l.opening.shape == photometry::LuminousOpening::Shape::point) {
      s.fail(
          "an observers surface needs every luminaire's luminous area (UGR's luminance is the "
          "intensity over the projected area); " +
          l.label + " has a point emitter: give it an \"emitter\" with its luminous opening");
    }
  }
}

// Luminaires outside every room or inside an obstacle are legal (light may enter through an
// opening later) but usually a typo: warn, naming the luminaire.
void warn_about_luminaires(Scene& scene) {
  if (scene.rooms.empty()) return;
  for (const auto& l : scene.luminaires) {
    const Vec3& p = l.pose.position;
    bool inside = false;
    for (const auto& r : scene.rooms) {
      if (!inside_room(r, p)) continue;
      inside = true;
      for (const auto& o : r.obstacles) {
        if (p.z > o.z0 && p.z < o.z1 &&
            geometry::locate(Vec2(p.x, p.y), o.footprint, 0.0) == geometry::Location::inside) {
          scene.warnings.push_back(l.label + ": inside obstacle \"" + o.name + "\" of room \"" +
                                   r.name + "\"");
        }
      }
    }
    if (!inside) scene.warnings.push_back(l.label + ": outside every room");
  }
}

}  // namespace

Project parse_project(const nlohmann::json& doc, const std::string& label,
                      const std::filesystem::path& base_dir) {
  const JsonDocument document(doc, label);
  const JsonValue root = document.root();
  root.expect_object();
  const auto format = root.at("format");
  if (format.as_string() != kProjectFormat) {
    format.fail(std::string("expected \"") + kProjectFormat + "\", got \"" + format.as_string() +
                "\"");
  }
  Project project;
  Scene& scene = project.scene;
  scene.name = root.has("name") ? root.at("name").as_string() : "unnamed project";
  if (auto s = root.find("settings")) {
    scene.settings = parse_settings(*s);
    s->report_unqueried();
  }

  const FilePolicy files{base_dir, scene.settings.allow_files_outside_project};
  const auto ph = root.at("photometry");
  if (!ph.is_object())
    ph.fail("expected an object of named entries, got " + json_type_name(ph.raw()));
  check_count(ph, kMaxPhotometryEntries, "photometry entries");
  for (const auto& [key, _] : ph.raw().items()) {
    const auto entry = ph.at(key.c_str());
    auto p = parse_photometry_entry(entry, files);
    entry.report_unqueried();
    // The reader's warnings name the file; say which entry loaded it, once per entry.
    for (const auto& w : p.warnings) scene.warnings.push_back("photometry \"" + key + "\": " + w);
    scene.photometry.emplace(key, std::move(p));
  }
  const auto rooms = root.at("rooms");
  check_count(rooms, kMaxRooms, "rooms");
  size_t obstacles = 0;
  for (const auto& r : rooms.items()) {
    // Counted before any is built: each is CGAL geometry.
    if (auto o = r.find("obstacles"); o && o->is_array()) {
      obstacles += o->raw().size();
      if (obstacles > kMaxObstacles) {
        o->fail("the project would have " + std::to_string(obstacles) +
                " obstacles, more than the limit of " + std::to_string(kMaxObstacles));
      }
    }
    Room room = parse_room(r, scene.warnings);
    r.report_unqueried();
    for (const auto& other : scene.rooms) {
      if (other.name == room.name)
        r.at("name").fail("a room named \"" + room.name + "\" already exists");
    }
    scene.rooms.push_back(std::move(room));
  }
  size_t index = 0;
  for (const auto& l : root.at("luminaires").items()) {
    parse_luminaire(l, index++, scene, scene.luminaires);
    l.report_unqueried();
  }
  warn_about_luminaires(scene);
  const auto surfaces = root.at("surfaces");
  check_count(surfaces, kMaxSurfaces, "surfaces");
  GridBudget budget(scene.luminaires.size());
  OutputNames outputs;
  std::set<std::string> names;
  for (const auto& s : surfaces.items()) {
    auto grids = parse_surface(s, scene, budget);
    check_observers_inputs(s, scene);
    if (auto r = s.find("requirements")) parse_requirements(*r, s, surfaces, project.requirements);
    record_emergency_surfaces(s, grids, scene.emergency_surfaces);
    s.report_unqueried();
    for (auto& grid : grids) {
      const auto name_v = s.at("name");
      if (!names.insert(grid.name).second)
        name_v.fail("a surface named \"" + grid.name + "\" already exists");
      if (names.size() > kMaxSurfaceGrids) {
        name_v.fail("the surfaces would give " + std::to_string(names.size()) +
                    " grids, more than the limit of " + std::to_string(kMaxSurfaceGrids));
      }
      check_name_length(name_v, grid.name);  // room_surfaces: "<name> wall 12"
      outputs.claim(name_v, grid.name);
      scene.surfaces.push_back(std::move(grid));
    }
  }
  if (scene.surfaces.empty()) surfaces.fail("expected at least one calculation surface");
  // IES TILT tables hold for the lamp as measured; a luminaire turned in the scene gets its
  // file's factor at its actual tilt, once, here, so every later stage sees the scaled output.
  apply_tilt_factors(scene);
  // Legal input that is usually a mistake (millimetres, kilolumens, radians, ...): warnings.
  add_sanity_warnings(scene, root);
  root.report_unqueried();
  return project;
}

Project parse_project_text(std::string_view text, const std::string& label,
                           const std::filesystem::path& base_dir) {
  return parse_project(parse_json_text(text, label), label, base_dir);
}

Project load_project(const std::filesystem::path& file) {
  // JSON-level messages name the file as given; the scene's name only its file name. The bytes
  // are read once: the hash in results.json is of exactly what was parsed.
  const std::string text = read_bounded_file(file);
  Project project = parse_project(parse_json_text(text, file.string()), file.filename().string(),
                                  file.parent_path());
  project.scene.project_file = file;
  project.scene.project_sha256 = sha256_hex(text);
  return project;
}

}  // namespace luxgrid::project
