#pragma once
// The project loader's parts (project/project_file.cpp calls them in the file's order), one file
// per kind of object: settings, photometry, rooms, luminaires, surfaces, emergency, and the value
// readers they share (project_values.cpp). Internal to project/: the loader's interface is
// project/project_file.h.
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "calc/scene.h"
#include "geometry/surface_grid.h"
#include "photometry/photometry.h"
#include "project/json_reader.h"
#include "project/project_limits.h"
#include "util/error.h"

namespace luxgrid::project::parts {

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
std::string count_text(double n);

// Coordinates and lengths in metres, within kMaxCoordinate_m of the origin.
double coordinate(const JsonValue& v);

// An array or object of at most `limit` entries, checked before any entry is read.
void check_count(const JsonValue& v, std::size_t limit, const char* what);

Vec3 point3(const JsonValue& v);
Vec2 point2(const JsonValue& v);
double positive_length(const JsonValue& v);

// A surface's "spacing" (`spacing`, read from surface `s`): metres, or "auto" for the rule
// geometry::auto_spacing gives a surface whose longer side is `longer_side`.
double parse_spacing(const JsonValue& s, const std::optional<JsonValue>& spacing,
                     double longer_side);

const calc::Room& find_room(const JsonValue& where, const calc::Scene& scene,
                            const std::string& name);
std::size_t active_points(const geometry::SurfaceGrid& g);

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

// openings and daylight (project_daylight.cpp): after the rooms, into `scene`.
void parse_openings(const JsonValue& openings, calc::Scene& scene);
calc::DaylightInputs parse_daylight(const JsonValue& d);
// daylight.obstructions (`list`): boxes outside every room of `scene` (docs/project-format.md).
std::vector<calc::ExteriorObstruction> parse_obstructions(const JsonValue& list,
                                                          const calc::Scene& scene);
// daylight.en17037's reference planes (`en17037`), once the surfaces are read: each a workplane
// surface (every workplane when none is named), top-lit when all its room's openings are in the
// ceiling; a warning for a plane not at EN 17037's height and border.
void resolve_en17037_planes(const JsonValue& en17037, const JsonValue& surfaces,
                            calc::Scene& scene);

// settings (project_settings.cpp).
calc::Settings parse_settings(const JsonValue& s);

// photometry (project_photometry.cpp).
// Where photometry files may come from: the project file's folder tree, unless the project
// says otherwise (settings.allow_files_outside_project).
struct FilePolicy {
  std::filesystem::path base_dir;  // relative paths start here
  bool allow_outside = false;
};
photometry::Photometry parse_photometry_entry(const JsonValue& e, const FilePolicy& policy);

// rooms (project_rooms.cpp). Warnings (a clockwise outline reversed) go to `warnings`.
calc::Room parse_room(const JsonValue& r, std::vector<Warning>& warnings);

// luminaires (project_luminaires.cpp): luminaire number `index` of the file, appended to `out`
// (an array gives many).
void parse_luminaire(const JsonValue& l, std::size_t index, const calc::Scene& scene,
                     std::vector<calc::Luminaire>& out);
// Luminaires outside every room or inside an obstacle are legal (light may enter through an
// opening later) but usually a typo: warn at `entry`, naming the luminaire, for each luminaire
// from number `first` on (those the entry gave).
void warn_about_luminaires(const JsonValue& entry, std::size_t first, calc::Scene& scene);

// surfaces (project_surfaces.cpp).
// Grid points promised so far over all surfaces. Each surface is charged its point count,
// computed in double, before its grid is built: nothing is allocated for a refused grid. The
// luminaire-point pairs (the direct calculation's work) are charged at the same time. A budget
// that only counts makes the surface readers stop once a surface is charged, before its grid is
// built: the loader charges every surface so, then builds them (the total is known before the
// first point is allocated).
class GridBudget {
 public:
  enum class Mode { build, count_only };
  explicit GridBudget(size_t luminaires, Mode mode = Mode::build)
      : luminaires_(static_cast<double>(luminaires)), mode_(mode) {}
  bool count_only() const { return mode_ == Mode::count_only; }
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
  Mode mode_;
  double used_ = 0.0;
  double views_ = 0.0;
};

// One surface entry gives one grid, or several for room_surfaces ("<name> floor", ...).
std::vector<geometry::SurfaceGrid> parse_surface(const JsonValue& s, const calc::Scene& scene,
                                                 GridBudget& budget);
// A surface's name becomes its output file names; kMaxSurfaceNameLength keeps them short enough.
void check_name_length(const JsonValue& where, const std::string& name);
// The output files claimed so far (util/output_names.h), compared ignoring case: on a
// case-insensitive file system A.csv and a.csv are one file, and one surface's results would
// silently replace another's.
class OutputNames {
 public:
  void claim(const JsonValue& where, const std::string& surface);

 private:
  std::map<std::string, std::string> owner_;  // lower-case file name -> surface name
};
// UGR (calc/glare) divides by the background luminance from reflected light and by each
// luminaire's projected luminous area: an observers surface refuses a project that turns
// reflections off or has a luminaire without a luminous area (a point emitter).
void check_observers_inputs(const JsonValue& s, const calc::Scene& scene);

// Observers in impossible places (project/observer_places.cpp), refused at the observer's "at":
// inside an obstacle, inside a luminaire's luminous opening, or, when a luminaire counts in one
// of its views, outside every room or in a room whose surfaces all have reflectance 0 (no
// reflected light: UGR unbounded). An observer nearer a luminaire than CIE 117's 0.1 sr source
// (calc/glare/luminous_solid_angle.h) gets a warning there. `grid` is the surface's grid.
void check_observer_places(const JsonValue& s, const geometry::SurfaceGrid& grid,
                           calc::Scene& scene);

// emergency (project_emergency.cpp) [EN1838].
// A luminaire's "emergency" entry [EN1838]: {"fraction": f} of its output (0 < f <= 1),
// {"flux_lm": F} (its own distribution scaled to F lumens, at most its normal flux) or
// {"photometry": "key"} (a separate photometry entry, e.g. the emergency module's own file).
calc::EmergencyOutput parse_emergency_output(const JsonValue& e, const calc::Scene& scene,
                                             const photometry::Photometry& own);
// EN 1838 surfaces (calc/emergency_surfaces.h), on the floor, horizontal illuminance:
// "escape_route": {"path": [[x, y], ...], "width": w, "floor_z": z} gives the grids
// "<name> centre line" and "<name> band"; "open_area": {"room": r, "outline": [[x, y], ...]} the
// room's floor (or the outline's, at the room's floor) without a 0.5 m border.
std::vector<geometry::SurfaceGrid> parse_emergency_surface(const JsonValue& s,
                                                           const calc::Scene& scene,
                                                           const std::string& name,
                                                           GridBudget& budget);
// The EN 1838 role of each grid an escape_route or open_area entry gave (in
// parse_emergency_surface's order).
void record_emergency_surfaces(const JsonValue& s, const std::vector<geometry::SurfaceGrid>& grids,
                               std::vector<calc::EmergencySurface>& out);

}  // namespace luxgrid::project::parts
