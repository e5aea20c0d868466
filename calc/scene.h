#pragma once
// The scene as the calculation sees it: everything in the project file, resolved, validated and
// in SI units and radians. Built by project/project_file, read by calc/plan, calc/direct, report/.
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>

#include "calc/daylight_inputs.h"
#include "calc/emergency_surfaces.h"
#include "calc/scene_notes.h"
#include "geometry/room.h"
#include "geometry/surface_grid.h"
#include "photometry/photometry.h"
#include "util/error.h"

namespace luxgrid::calc {

enum class Quality { draft, standard, high, reference };
enum class NearFieldMode { automatic, always, never };
enum class IndirectMode { automatic, off, on };
// Which lighting is calculated: the normal lighting, the emergency lighting of EN 1838
// (calc/emergency_scene.h: direct light only, from the luminaires' emergency output), or daylight
// (docs/daylight.md: the sky through the openings, no luminaires).
enum class LightingScene { normal, emergency, daylight };

const char* to_string(Quality q);
const char* to_string(LightingScene s);  // "normal", "emergency", "daylight"
std::optional<Quality> quality_from_string(const std::string& s);

// The maintenance factor's parts [CIE97]: MF = LLMF x LSF x LMF x RSMF (lamp lumen maintenance,
// lamp survival, luminaire maintenance, room surface maintenance).
struct MaintenanceFactors {
  double LLMF = 1.0;
  double LSF = 1.0;
  double LMF = 1.0;
  double RSMF = 1.0;
  double product() const { return LLMF * LSF * LMF * RSMF; }
};

struct Settings {
  Quality quality = Quality::standard;
  NearFieldMode near_field = NearFieldMode::automatic;
  IndirectMode indirect = IndirectMode::automatic;
  std::string
      near_field_model;  // empty: the quality's rung; else a rung by name (docs/nearfield.md)
  int bounces = 0;       // 0 means "auto" (iterate until converged)
  double maintenance_factor = 1.0;  // MF: every E is (E_direct + E_indirect) x MF
  // Set when the project gives the parts (settings.maintenance as an object); maintenance_factor
  // is then their product.
  std::optional<MaintenanceFactors> maintenance_parts;
  LightingScene scene = LightingScene::normal;  // settings.scene, or `calc --scene`
  // Photometry files may lie outside the project file's folder (absolute paths, ../); off by
  // default, so a project received from elsewhere cannot read arbitrary files.
  bool allow_files_outside_project = false;
};

struct Reflectances {
  double floor = 0.2;
  double walls = 0.5;
  double ceiling = 0.7;
};

struct Room {
  std::string name;
  std::vector<Vec2> outline;  // floor polygon seen from above, counter-clockwise
  double floor_z = 0.0;
  double height = 0.0;
  Reflectances reflectance;
  // Boxes and prisms inside the room (geometry/room.h), footprints counter-clockwise.
  std::vector<geometry::Obstacle> obstacles;
};

// Where a luminaire sits and how it is turned: world = position + rotation * local.
struct Pose {
  Vec3 position{0.0};
  glm::dmat3 rotation{1.0};  // luminaire frame -> world frame
};

// Rotation [rx, ry, rz] in radians about the world x, then y, then z axis (docs/project-format.md).
glm::dmat3 rotation_xyz(double rx, double ry, double rz);

// A luminaire's emergency output [EN1838]: its own distribution times `factor` (a fraction of
// its output, or the emergency flux over the file's flux), or a separate photometry entry.
struct EmergencyOutput {
  double factor = 1.0;     // on the luminaire's own distribution; 1 with `photometry`
  std::string photometry;  // non-empty: the photometry entry giving the emergency distribution
  double flux_lm = 0.0;    // the flux asked for ("flux_lm"), lm; 0: not asked for
};

struct Luminaire {
  std::string label;       // "luminaire 3" or "luminaire 3 [1,0]" for array members
  std::string photometry;  // key into Scene::photometry
  Pose pose;
  photometry::DistributionPtr distribution;
  photometry::LuminousOpening opening;  // from the file, or the project's "emitter" override
  // The luminaire's output in the emergency scene (its "emergency" entry); none: it stays dark.
  std::optional<EmergencyOutput> emergency;
};

struct Scene {
  std::string name;
  std::filesystem::path project_file;
  std::string
      project_sha256;  // of the project file's bytes as read (util/sha256.h); empty in memory
  Settings settings;
  std::map<std::string, photometry::Photometry> photometry;
  std::vector<Room> rooms;
  std::vector<Luminaire> luminaires;
  std::vector<geometry::SurfaceGrid> surfaces;
  // The grids of escape routes and open areas (calc/emergency_surfaces.h), checked against
  // EN 1838 in the emergency scene.
  std::vector<EmergencySurface> emergency_surfaces;
  // Windows and roof lights, and the sky (docs/daylight.md): the daylight scene's input.
  std::vector<DaylightOpening> openings;
  std::optional<DaylightInputs> daylight;
  // What was done to the project before the calculation (the emergency scene's choices): the
  // pipeline copies them into the plan's notes.
  std::vector<SceneNote> notes;
  // Legal but suspicious input, each at its place in the project file and naming the object
  // (`p.json:5:16 /rooms/0/outline: room "L": the outline is clockwise; reversed to
  // counter-clockwise`; util/error.h). The CLI prints them; results list them.
  std::vector<Warning> warnings;
};

}  // namespace luxgrid::calc
