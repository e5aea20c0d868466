#include "calc/emergency_scene.h"

#include <algorithm>

#include "calc/luminaire_tilt.h"
#include "calc/scaled_distribution.h"
#include "util/error.h"

namespace luxgrid::calc {

namespace {

// The luminaire's distribution in the emergency scene. Its own distribution already carries
// the file's TILT factor at the luminaire's tilt (apply_tilt_factors); a separate photometry entry
// gets its own file's factor here, the same way.
photometry::DistributionPtr emergency_distribution(const Scene& scene, const Luminaire& lum) {
  const EmergencyOutput& em = *lum.emergency;
  if (em.photometry.empty()) {
    return std::make_shared<ScaledDistribution>(lum.distribution, em.factor);
  }
  const photometry::Photometry& p = scene.photometry.at(em.photometry);
  if (!p.tilt) return p.distribution;
  const double tilt =
      p.tilt->factor_at(lamp_tilt_deg(lum.pose.rotation, p.tilt->lamp_to_luminaire_geometry));
  return std::make_shared<ScaledDistribution>(p.distribution, tilt);
}

}  // namespace

Scene make_emergency_scene(const Scene& normal) {
  Scene scene = normal;
  scene.settings.scene = LightingScene::emergency;
  // EN 1838 counts direct light only: reflections off walls and ceilings are not relied on.
  scene.settings.indirect = IndirectMode::off;
  scene.luminaires.clear();
  SceneNote note;  // emergency_scene
  for (const auto& lum : normal.luminaires) {
    if (!lum.emergency) continue;
    Luminaire e = lum;
    e.distribution = emergency_distribution(normal, lum);
    if (!lum.emergency->photometry.empty()) e.photometry = lum.emergency->photometry;
    scene.luminaires.push_back(std::move(e));
    const EmergencyOutput& em = *lum.emergency;
    if (note.outputs.size() < SceneNote::kListedOutputs)
      note.outputs.push_back({lum.label, em.factor, em.flux_lm, em.photometry});
  }
  if (scene.luminaires.empty()) {
    throw InputError(
        "the emergency scene has no light: no luminaire has an \"emergency\" entry "
        "(give the emergency luminaires \"emergency\": {\"fraction\": ...}, {\"flux_lm\": ...} "
        "or {\"photometry\": ...})");
  }
  const auto is_observers = [](const geometry::SurfaceGrid& g) {
    return g.kind == geometry::SurfaceGrid::Kind::observers;
  };
  const auto dropped = std::count_if(scene.surfaces.begin(), scene.surfaces.end(), is_observers);
  scene.surfaces.erase(std::remove_if(scene.surfaces.begin(), scene.surfaces.end(), is_observers),
                       scene.surfaces.end());
  if (scene.surfaces.empty()) {
    throw InputError(
        "the emergency scene has no calculation surface: observers surfaces (glare) are not "
        "calculated in it; add an escape_route or open_area surface");
  }
  note.luminaires = scene.luminaires.size();
  note.of_luminaires = normal.luminaires.size();
  scene.notes.push_back(std::move(note));
  if (dropped > 0) {
    SceneNote left_out;
    left_out.kind = SceneNote::Kind::observers_left_out;
    left_out.observers = static_cast<std::size_t>(dropped);
    scene.notes.push_back(std::move(left_out));
  }
  return scene;
}

}  // namespace luxgrid::calc
