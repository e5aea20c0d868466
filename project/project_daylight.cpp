// The project's "openings" (windows and roof lights in room faces) and "daylight" (sky, sun,
// site, ground): docs/daylight.md, docs/project-format.md.
#include <cmath>
#include <cstdio>

#include "calc/daylight/clear_glass.h"
#include "calc/opening_placement.h"
#include "geometry/polygon.h"
#include "geometry/room.h"
#include "project/project_parts.h"

namespace luxgrid::project::parts {

using namespace calc;

namespace {

DaylightOpening parse_opening(const JsonValue& o, size_t index, const Scene& scene) {
  o.expect_object();
  DaylightOpening out;
  out.name = o.has("name") ? o.at("name").as_string() : "opening " + std::to_string(index);
  const auto room_v = o.at("room");
  const Room& room = find_room(room_v, scene, room_v.as_string());
  out.room = static_cast<size_t>(&room - scene.rooms.data());
  const auto poly = o.at("polygon");
  check_count(poly, kMaxOpeningCorners, "opening corners");
  for (const auto& p : poly.items()) out.polygon.push_back(point3(p));
  if (out.polygon.size() < 3)
    poly.fail("expected at least 3 corners, got " + std::to_string(out.polygon.size()));
  const OpeningPlacement placed = place_opening(room, out.polygon);
  if (!placed.found) poly.fail("opening \"" + out.name + "\" " + placed.reason);
  out.face = placed.face, out.inward_normal = placed.inward_normal;
  // A simple polygon of non-zero area in its face (normalize_outline's checks, in the face's
  // coordinates).
  std::vector<Vec2> flat = face_coordinates(room, out.face, out.polygon);
  at_place(poly, [&] { return geometry::normalize_outline(flat, "opening \"" + out.name + "\""); });
  if (auto g = o.find("glazing")) {
    g->expect_object();
    const auto t = g->at("transmittance");
    const double tn = t.as_number();
    if (!(tn > 0.0 && tn <= 1.0))
      t.fail("expected a normal transmittance in (0, 1], got " + number_text(tn));
    if (tn > daylight::lossless_normal_transmittance()) {
      t.fail("a clear pane of refractive index 1.52 transmits at most " +
             number_text(daylight::lossless_normal_transmittance()) +
             " at normal incidence (its two surfaces reflect the rest); got " + number_text(tn) +
             " (an unglazed opening: leave out \"glazing\")");
    }
    out.glazing_transmittance = tn;
    g->report_unqueried();
  }
  for (const auto& [key, value] :
       {std::pair<const char*, double*>{"frame_factor", &out.frame_factor},
        {"maintenance_factor", &out.maintenance_factor}}) {
    if (auto f = o.find(key)) {
      *value = f->as_number_in(0.0, 1.0);
      if (!(*value > 0.0)) f->fail("expected a factor in (0, 1], got 0");
    }
  }
  return out;
}

// "2024-06-21T12:30" (local standard time, seconds optional).
daylight::LocalTime parse_local_time(const JsonValue& v) {
  const std::string text = v.as_string();
  daylight::LocalTime t;
  int consumed = 0;
  double second = 0.0;
  const int fields = std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d%n", &t.year, &t.month, &t.day,
                                 &t.hour, &t.minute, &consumed);
  bool ok = fields == 5;
  if (ok && consumed < static_cast<int>(text.size())) {
    int more = 0;
    ok = std::sscanf(text.c_str() + consumed, ":%lf%n", &second, &more) == 1 &&
         consumed + more == static_cast<int>(text.size());
  }
  ok = ok && t.month >= 1 && t.month <= 12 && t.day >= 1 && t.day <= 31 && t.hour >= 0 &&
       t.hour <= 23 && t.minute >= 0 && t.minute <= 59 && second >= 0.0 && second < 60.0;
  if (!ok)
    v.fail("expected a local standard time as \"YYYY-MM-DDThh:mm\" (or \"...:ss\"), got \"" + text +
           "\"");
  t.second = second;
  return t;
}

daylight::SkyModel parse_sky(const JsonValue& s) {
  s.expect_object();
  const auto type = s.at("type");
  const std::string expected =
      "expected a CIE general sky type 1 to 15, \"cie-overcast\" or \"uniform\", got ";
  std::optional<daylight::SkyModel> sky;
  if (type.is_number()) {
    const double n = type.as_number();
    if (n == std::floor(n) && n >= 1 && n <= daylight::kCieGeneralSkyTypes)
      sky = daylight::sky_from_name(std::to_string(static_cast<int>(n)));
    if (!sky) type.fail(expected + type.raw().dump());
  } else if (type.is_string()) {
    const std::string name = type.as_string();
    if (name == "cie-overcast" || name == "uniform") sky = daylight::sky_from_name(name);
    if (!sky) type.fail(expected + "\"" + name + "\"");
  } else {
    type.fail(expected + json_type_name(type.raw()));
  }
  s.report_unqueried();
  return *sky;
}

// daylight.en17037: the site's median, the level, the reference planes by name (resolved
// against the surfaces once they are read: resolve_en17037_planes).
daylight::En17037Request parse_en17037(const JsonValue& e) {
  e.expect_object();
  daylight::En17037Request out;
  out.median_external_diffuse_lx = e.at("median_external_diffuse_lx").as_positive();
  if (auto l = e.find("level")) {
    const std::string name = l->is_string() ? l->as_string() : l->raw().dump();
    const auto level = daylight::en17037_level_from_name(name);
    if (!level || !l->is_string())
      l->fail("expected an EN 17037 level \"minimum\", \"medium\" or \"high\", got " +
              (l->is_string() ? "\"" + name + "\"" : name));
    out.level = *level;
  }
  if (auto planes = e.find("reference_planes")) {
    check_count(*planes, kMaxSurfaces, "reference planes");
    for (const auto& p : planes->items()) out.planes.push_back({p.as_string(), false});
    if (out.planes.empty()) planes->fail("expected at least one workplane surface's name");
  }
  e.report_unqueried();
  return out;
}

}  // namespace

void resolve_en17037_planes(const JsonValue& en17037, const JsonValue& surfaces, Scene& scene) {
  daylight::En17037Request& request = *scene.daylight->en17037;
  std::vector<JsonValue> workplanes;  // the surfaces entries with a "workplane"
  for (const auto& s : surfaces.items())
    if (s.has("workplane")) workplanes.push_back(s);
  const auto named = [&](const std::string& name) -> std::optional<JsonValue> {
    for (const auto& w : workplanes)
      if (w.at("name").as_string() == name) return w;
    return std::nullopt;
  };
  std::vector<JsonValue> chosen;
  if (request.planes.empty()) {
    if (workplanes.empty())
      en17037.fail(
          "EN 17037 is assessed on a reference plane: give a workplane surface (0.85 m above the "
          "floor, border 0.5 m)");
    for (const auto& w : workplanes) request.planes.push_back({w.at("name").as_string(), false});
    chosen = workplanes;
  } else {
    const auto names = en17037.at("reference_planes");
    for (std::size_t k = 0; k < request.planes.size(); ++k) {
      const auto w = named(request.planes[k].surface);
      if (!w)
        names.item(k).fail("no workplane surface is named \"" + request.planes[k].surface +
                           "\" (EN 17037's reference plane is a workplane: 0.85 m above the "
                           "floor, border 0.5 m)");
      chosen.push_back(*w);
    }
  }
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const auto w = chosen[k].at("workplane");
    const Room& room = find_room(w.at("room"), scene, w.at("room").as_string());
    const std::size_t room_index = static_cast<std::size_t>(&room - scene.rooms.data());
    // Top-lit: every opening of the room in its ceiling (roof lights only).
    std::size_t openings = 0, roof_lights = 0;
    for (const DaylightOpening& o : scene.openings) {
      if (o.room != room_index) continue;
      ++openings;
      roof_lights += o.face.kind == RoomFaceRef::Kind::ceiling;
    }
    request.planes[k].top_lit = openings > 0 && roof_lights == openings;
    const double height = w.at("height").as_number();
    const double border = w.has("border") ? w.at("border").as_number() : 0.0;
    // 1 mm: a plane typed as 0.85 is the standard's.
    if (std::abs(height - daylight::kEn17037PlaneHeight_m) > 1e-3 ||
        std::abs(border - daylight::kEn17037PlaneBorder_m) > 1e-3) {
      scene.warnings.push_back(
          {w.location(),
           "EN 17037's reference plane lies " + number_text(daylight::kEn17037PlaneHeight_m) +
               " m above the floor with a " + number_text(daylight::kEn17037PlaneBorder_m) +
               " m border; workplane \"" + request.planes[k].surface + "\" has " +
               number_text(height) + " m and " + number_text(border) +
               " m: its EN 17037 fractions are not the standard's"});
    }
  }
}

std::vector<ExteriorObstruction> parse_obstructions(const JsonValue& list, const Scene& scene) {
  check_count(list, kMaxExteriorObstructions, "exterior obstructions");
  std::vector<ExteriorObstruction> out;
  for (const auto& o : list.items()) {
    o.expect_object();
    ExteriorObstruction b;
    b.name = o.has("name") ? o.at("name").as_string() : "obstruction " + std::to_string(out.size());
    const auto box = o.at("box");
    box.expect_object();
    b.min = point3(box.at("min")), b.max = point3(box.at("max"));
    box.report_unqueried();
    if (!(b.min.x < b.max.x && b.min.y < b.max.y && b.min.z < b.max.z))
      box.fail("exterior obstruction \"" + b.name +
               "\": expected min < max in x, y and z (a box of positive volume)");
    b.reflectance = o.at("reflectance").as_number_in(0.0, 1.0);
    // Outside every room: touching a room's outside face is allowed (an overhang sits on the
    // facade), sharing volume is not (it would be inside the room, where obstacles belong).
    const geometry::Polygon2 footprint{
        {b.min.x, b.min.y}, {b.max.x, b.min.y}, {b.max.x, b.max.y}, {b.min.x, b.max.y}};
    for (const Room& room : scene.rooms) {
      if (b.min.z < room.floor_z + room.height && b.max.z > room.floor_z &&
          geometry::polygons_overlap(footprint, room.outline))
        box.fail("exterior obstruction \"" + b.name + "\" reaches into room \"" + room.name +
                 "\" (an obstruction lies outside every room; inside one, give it as an obstacle "
                 "of the room)");
    }
    o.report_unqueried();
    out.push_back(std::move(b));
  }
  return out;
}

void parse_openings(const JsonValue& openings, Scene& scene) {
  check_count(openings, kMaxOpenings, "openings");
  size_t index = 0;
  for (const auto& o : openings.items()) {
    DaylightOpening opening = parse_opening(o, index++, scene);
    o.report_unqueried();
    // Openings of one face may touch, not overlap: the light through the shared part would count
    // twice.
    for (const DaylightOpening& other : scene.openings) {
      if (other.room != opening.room || other.face.kind != opening.face.kind ||
          other.face.wall != opening.face.wall)
        continue;
      const Room& room = scene.rooms[opening.room];
      if (geometry::polygons_overlap(face_coordinates(room, opening.face, opening.polygon),
                                     face_coordinates(room, other.face, other.polygon))) {
        o.at("polygon").fail("opening \"" + opening.name + "\" overlaps opening \"" + other.name +
                             "\" in the same face");
      }
    }
    scene.openings.push_back(std::move(opening));
  }
}

DaylightInputs parse_daylight(const JsonValue& d) {
  d.expect_object();
  DaylightInputs out;
  out.sky = parse_sky(d.at("sky"));
  if (auto e = d.find("diffuse_horizontal_lx")) out.diffuse_horizontal_lx = e->as_positive();
  if (auto e = d.find("en17037")) out.en17037 = parse_en17037(*e);
  if (auto g = d.find("ground")) {
    g->expect_object();
    if (auto r = g->find("reflectance")) out.ground_reflectance = r->as_number_in(0.0, 1.0);
    g->report_unqueried();
  }
  if (auto s = d.find("site")) {
    s->expect_object();
    if (auto v = s->find("latitude_deg")) out.site.latitude_deg = v->as_number_in(-90.0, 90.0);
    if (auto v = s->find("longitude_deg")) out.site.longitude_deg = v->as_number_in(-180.0, 180.0);
    if (auto v = s->find("timezone_h")) out.site.timezone_h = v->as_number_in(-14.0, 14.0);
    if (auto v = s->find("north_angle_deg")) out.site.north_angle_deg = v->as_number_in(-360, 360);
    if (auto v = s->find("elevation_m")) out.site.elevation_m = v->as_number_in(-500.0, 9000.0);
    s->report_unqueried();
  }
  if (auto s = d.find("sun")) {
    s->expect_object();
    if (s->has("local_time")) {
      const auto site = d.find("site");
      if (!site || !site->has("latitude_deg") || !site->has("longitude_deg") ||
          !site->has("timezone_h"))
        s->at("local_time")
            .fail(
                "the sun's position at a local time needs the site's \"latitude_deg\", "
                "\"longitude_deg\" and \"timezone_h\" (daylight.site)");
      out.local_time = parse_local_time(s->at("local_time"));
      out.sun_from_site = true;
      out.sun = daylight::sun_at(out.site, out.local_time);
    } else {
      daylight::SunPosition sun;
      sun.altitude_deg = s->at("altitude_deg").as_number_in(-90.0, 90.0);
      sun.azimuth_deg = s->at("azimuth_deg").as_number_in(-360.0, 360.0);
      out.sun = sun;
    }
    if (auto e = s->find("direct_normal_lx")) {
      // Direct sun switched on (docs/daylight.md, "Direct sunlight"): a finite positive
      // illuminance, with the sun above the horizon (below it there is no direct sun to ask for).
      const double lx = e->as_number();
      if (!(lx > 0.0) || !std::isfinite(lx))
        e->fail("expected the sun's direct normal illuminance in lx, a number > 0, got " +
                number_text(lx) + " (no direct sun: leave out \"direct_normal_lx\")");
      if (!(out.sun->altitude_deg > 0.0))
        e->fail("direct sun asked for, but the sun is " + number_text(out.sun->altitude_deg) +
                " degrees above the horizon: it shines through no opening (leave out "
                "\"direct_normal_lx\")");
      out.direct_normal_lx = lx;
    }
    s->report_unqueried();
  }
  if (out.sky.kind == daylight::SkyKind::cie_general) {
    if (!out.sun)
      d.at("sky").at("type").fail(
          "a CIE general sky is shaped by the sun: give daylight.sun (\"altitude_deg\" and "
          "\"azimuth_deg\", or \"local_time\" with daylight.site)");
    if (!(out.sun->altitude_deg > 0.0))
      d.at("sun").fail("the sun is " + number_text(out.sun->altitude_deg) +
                       " degrees above the horizon: a CIE general sky needs the sun above it");
    out.sky.sun = daylight::sun_direction(*out.sun, out.site.north_angle_deg);
  }
  return out;
}

}  // namespace luxgrid::project::parts
