#include "calc/far_field_bounds.h"

#include <tbb/global_control.h>

#include "calc/nearfield/far_field_bound.h"

namespace luxgrid::calc {
namespace {

// Two openings are the same emitter when their polygons in the luminaire frame agree to this
// fraction of their size (rounding of the pose's rotation; a real difference is millimetres).
constexpr double kSameOpeningRelative = 1e-9;

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

}  // namespace

std::vector<std::string> attach_far_field_bounds(const Scene& scene, const Plan& plan,
                                                 std::vector<nearfield::Emitter>& emitters) {
  std::vector<std::string> lines;
  if (plan.near_switch != nearfield::NearFieldSwitch::automatic) return lines;
  const double tolerance = nearfield::promised_tolerance(plan.near_model);
  // The map's directions run on plain threads (the nearfield library has no TBB): as many as
  // the calculation may use (luxgrid --threads, LUXGRID_THREADS; cli/threads.h).
  const auto max_threads = static_cast<unsigned>(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  std::vector<Distinct> distinct;
  for (size_t i = 0; i < emitters.size(); ++i) {
    nearfield::Emitter& e = emitters[i];
    if (e.is_point()) continue;
    std::vector<Vec3> outline = local_outline(e);
    auto it = std::find_if(distinct.begin(), distinct.end(), [&](const Distinct& d) {
      return d.distribution == e.distribution.get() &&
             same_outline(d.outline, outline, e.largest_dimension_m);
    });
    if (it == distinct.end()) {
      distinct.push_back(
          {e.distribution.get(),
           std::move(outline),
           nearfield::build_far_field_bound(e, plan.near_model, tolerance, max_threads),
           scene.luminaires[i].photometry,
           {}});
      it = distinct.end() - 1;
    }
    it->members.push_back(i);
    e.far_bound = it->bound;
  }
  for (const Distinct& d : distinct) {
    const std::string who = d.members.size() == 1
                                ? scene.luminaires[d.members[0]].label
                                : std::to_string(d.members.size()) + " luminaires";
    lines.push_back("\"" + d.photometry + "\" (" + who + "): " + nearfield::describe(*d.bound));
  }
  return lines;
}

}  // namespace luxgrid::calc
