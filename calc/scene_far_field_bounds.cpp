#include "calc/scene_far_field_bounds.h"

#include <algorithm>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include "calc/direct.h"
#include "calc/nearfield/far_field_bound.h"
#include "calc/nearfield/illuminance.h"

namespace luxgrid::calc {
namespace {

// Two openings are the same emitter when their polygons in the luminaire frame agree to this
// fraction of their size (rounding of the pose's rotation; a real difference is millimetres).
constexpr double kSameOpeningRelative = 1e-9;
// Points per task when the map's demand is marked (each costs about 0.1 us: a few thousand
// make a task worth its scheduling).
constexpr std::size_t kMapDemandGrain = 4096;

std::vector<Vec3> local_outline(const nearfield::Emitter& e) {
  std::vector<Vec3> out;
  for (const Vec3& v : e.vertices) out.push_back(e.world_to_local * (v - e.centroid));
  return out;
}

bool same_outline(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double size) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (glm::length(a[i] - b[i]) > kSameOpeningRelative * size) return false;
  return true;
}

struct Distinct {
  const photometry::IntensityDistribution* distribution;
  std::vector<Vec3> outline;
  std::shared_ptr<const nearfield::FarFieldBound> bound;
  std::string photometry;
  std::vector<size_t> members;
};

// Every pair direct light will compute for the members of one distinct emitter: the active
// points of every surface whose zone holds a member. Null when there are more than
// kMapDemandPairs (the whole map is then cheaper than marking them).
std::unique_ptr<nearfield::MapDemand> demand_of(const Scene& scene, const Plan& plan,
                                                const std::vector<nearfield::Emitter>& emitters,
                                                const std::vector<size_t>& members,
                                                const DirectReach& reach,
                                                const std::vector<std::vector<uint32_t>>& zones) {
  // Which zones light each member, then how many pairs that makes.
  std::vector<std::vector<char>> member_in_zone(members.size(),
                                                std::vector<char>(reach.zone_count(), 0));
  for (uint32_t z = 0; z < reach.zone_count(); ++z)
    for (size_t m = 0; m < members.size(); ++m) {
      const auto& lums = reach.zone(z).luminaires;
      member_in_zone[m][z] =
          std::binary_search(lums.begin(), lums.end(), static_cast<uint32_t>(members[m]));
    }
  size_t pairs = 0;
  for (size_t s = 0; s < scene.surfaces.size(); ++s)
    for (uint32_t z : zones[s])
      for (size_t m = 0; m < members.size(); ++m) pairs += member_in_zone[m][z];
  if (pairs > kMapDemandPairs) return nullptr;
  // In parallel over the members' pairs, and over the points of each surface (a scene of one
  // luminaire over many points has one member); the per-sample maximum does not depend on the
  // order.
  tbb::combinable<nearfield::MapDemand> parts;
  tbb::parallel_for(size_t{0}, members.size(), [&](size_t m) {
    const nearfield::Emitter& e = emitters[members[m]];
    for (size_t s = 0; s < scene.surfaces.size(); ++s) {
      const geometry::SurfaceGrid& grid = scene.surfaces[s];
      tbb::parallel_for(
          tbb::blocked_range<size_t>(0, grid.points.size(), kMapDemandGrain),
          [&](const tbb::blocked_range<size_t>& range) {
            nearfield::MapDemand& demand = parts.local();
            for (size_t i = range.begin(); i != range.end(); ++i) {
              if (!member_in_zone[m][zones[s][i]] || !(grid.active.empty() || grid.active[i]))
                continue;
              // The direction and distance FarFieldBound::weights is asked for (nearfield
              // switch_weights).
              const Vec3 r = grid.points[i] - e.centroid;
              const double d = glm::length(r);
              if (!(d > 0.0)) continue;
              const bool fixed_rule = nearfield::fixed_rule_may_serve(
                  e, receiver_of(grid.quantity, grid.normals[i]), plan.near_model,
                  reach.zone(zones[s][i]).visibility.get());
              demand.add(e.world_to_local * (r / d), d / e.largest_dimension_m, fixed_rule);
            }
          });
    }
  });
  auto demand = std::make_unique<nearfield::MapDemand>();
  parts.combine_each([&](const nearfield::MapDemand& part) { demand->merge(part); });
  return demand;
}

}  // namespace

std::vector<NearFarPlan> attach_far_field_bounds(const Scene& scene, const Plan& plan,
                                                 std::vector<nearfield::Emitter>& emitters,
                                                 const DirectReach* reach,
                                                 const std::vector<std::vector<uint32_t>>* zones) {
  std::vector<NearFarPlan> lines;
  if (plan.near_switch != nearfield::NearFieldSwitch::automatic) return lines;
  const double tolerance = nearfield::promised_tolerance(plan.near_model);
  std::vector<Distinct> distinct;
  for (size_t i = 0; i < emitters.size(); ++i) {
    const nearfield::Emitter& e = emitters[i];
    if (e.is_point()) continue;
    std::vector<Vec3> outline = local_outline(e);
    auto it = std::find_if(distinct.begin(), distinct.end(), [&](const Distinct& d) {
      return d.distribution == e.distribution.get() &&
             same_outline(d.outline, outline, e.largest_dimension_m);
    });
    if (it == distinct.end()) {
      distinct.push_back(
          {e.distribution.get(), std::move(outline), nullptr, scene.luminaires[i].photometry, {}});
      it = distinct.end() - 1;
    }
    it->members.push_back(i);
  }
  for (Distinct& d : distinct) {
    const std::unique_ptr<nearfield::MapDemand> demand =
        reach && zones ? demand_of(scene, plan, emitters, d.members, *reach, *zones) : nullptr;
    d.bound = nearfield::build_far_field_bound(emitters[d.members[0]], plan.near_model, tolerance,
                                               demand.get());
    for (size_t i : d.members) emitters[i].far_bound = d.bound;
    lines.push_back({{d.photometry, d.members.size(), scene.luminaires[d.members[0]].label},
                     nearfield::summarize(*d.bound)});
  }
  return lines;
}

}  // namespace luxgrid::calc
