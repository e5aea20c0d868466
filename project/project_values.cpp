// Values the loader's parts share: coordinates, counts, spacings, rooms by name.
#include "project/project_parts.h"

#include <cmath>

#include "geometry/workplane.h"

namespace luxgrid::project::parts {

// The loader builds calc's types (Scene, Room, Luminaire, Settings) on every line.
using namespace calc;

// A count computed in double (a 1e-300 m spacing gives 1e300 points per side): exact below
// 1e15, then in exponent form; never converted to an integer type, where it would overflow.
std::string count_text(double n) {
  if (!std::isfinite(n)) return "over 1e308";
  if (n >= 1e15) return number_text(n);
  return format_double("%.0f", n);
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

double parse_spacing(const JsonValue& s, const std::optional<JsonValue>& spacing,
                     double longer_side) {
  if (!spacing) s.fail("missing required key \"spacing\" (metres or \"auto\")");
  if (spacing->is_string()) {
    if (spacing->as_string() != "auto") spacing->fail("expected a number of metres or \"auto\"");
    return geometry::auto_spacing(longer_side);
  }
  return spacing->as_positive();
}

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

}  // namespace luxgrid::project::parts
