#include "report/energy.h"

#include <algorithm>
#include <cmath>

#include "geometry/polygon.h"
#include "report/map_frame.h"

namespace luxgrid::report {

std::optional<double> RoomEnergy::W_per_m2() const {
  if (!power_W || !(area_m2 > 0.0)) return std::nullopt;
  return *power_W / area_m2;
}

std::optional<double> RoomEnergy::W_per_m2_per_100lx() const {
  const auto density = W_per_m2();
  if (!density || !Eavg_lx || !(*Eavg_lx > 0.0)) return std::nullopt;
  return *density / (*Eavg_lx / 100.0);
}

std::vector<RoomEnergy> room_energy(const calc::Scene& scene,
                                    const std::vector<LuminaireType>& types,
                                    const calc::Results& results,
                                    const std::vector<RequirementCheck>& checks) {
  std::vector<RoomEnergy> out;
  for (const auto& room : scene.rooms) {
    RoomEnergy e;
    e.room = room.name;
    e.area_m2 = std::abs(geometry::signed_area(room.outline));
    double watts = 0.0;
    bool all_known = true;
    for (const auto& l : scene.luminaires) {
      if (geometry::locate(Vec2(l.pose.position), room.outline, 1e-6) ==
          geometry::Location::outside)
        continue;
      ++e.luminaires;
      const auto t = std::find_if(types.begin(), types.end(), [&](const LuminaireType& type) {
        return type.key == l.photometry;
      });
      const auto power = t == types.end() ? std::nullopt : t->power_W;
      if (power) {
        watts += *power;
      } else {
        all_known = false;
        if (std::find(e.without_power.begin(), e.without_power.end(), l.photometry) ==
            e.without_power.end())
          e.without_power.push_back(l.photometry);
      }
    }
    if (all_known && e.luminaires > 0) e.power_W = watts;
    // The reference surface: rank 0 with an Em requirement, 1 above the floor, 2 the floor.
    int best_rank = 3;
    for (const auto& s : results.surfaces) {
      const auto& g = s.grid;
      if (g.kind != geometry::SurfaceGrid::Kind::grid || glm::cross(g.u_dir, g.v_dir).z < 0.7)
        continue;
      if (map_frame(g, &scene).room != &room) continue;
      bool em = false;
      for (const auto& c : checks) em = em || (c.surface == g.name && c.quantity == "Em");
      const int rank = em ? 0 : g.origin.z > room.floor_z + 1e-6 ? 1 : 2;
      if (rank < best_rank) {
        best_rank = rank;
        e.reference_surface = g.name;
        e.Eavg_lx = s.stats.Eavg;
      }
    }
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace luxgrid::report
