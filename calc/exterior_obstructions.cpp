#include "calc/exterior_obstructions.h"

#include <algorithm>
#include <limits>

namespace luxgrid::calc {

Vec3 box_face_normal(int face) {
  Vec3 n{0.0};
  n[face / 2] = face % 2 == 1 ? 1.0 : -1.0;
  return n;
}

std::optional<ObstructionHit> first_exterior_obstruction(
    const std::vector<ExteriorObstruction>& obstructions, const Vec3& origin, const Vec3& dir) {
  std::optional<ObstructionHit> best;
  for (std::size_t k = 0; k < obstructions.size(); ++k) {
    const ExteriorObstruction& b = obstructions[k];
    // The ray's parameter interval inside each slab min <= x <= max; the box is met where the
    // three intervals overlap with positive length ahead of the origin (a ray grazing a face or
    // an edge meets nothing: it enters no interior). A ray starting inside a box meets it at 0.
    double enter = -std::numeric_limits<double>::infinity();
    double leave = std::numeric_limits<double>::infinity();
    int face = -1;
    bool missed = false;
    for (int axis = 0; axis < 3 && !missed; ++axis) {
      if (dir[axis] == 0.0) {
        missed = !(origin[axis] > b.min[axis] && origin[axis] < b.max[axis]);
        continue;
      }
      const double t_min = (b.min[axis] - origin[axis]) / dir[axis];
      const double t_max = (b.max[axis] - origin[axis]) / dir[axis];
      // Entering through the face whose outward normal opposes the ray.
      const double t_in = dir[axis] > 0.0 ? t_min : t_max;
      if (t_in > enter) enter = t_in, face = 2 * axis + (dir[axis] > 0.0 ? 0 : 1);
      leave = std::min(leave, dir[axis] > 0.0 ? t_max : t_min);
    }
    missed = missed || face < 0 || !(leave > std::max(enter, 0.0));
    if (missed) continue;
    const double distance_m = std::max(enter, 0.0);
    if (!best || distance_m < best->distance_m) best = ObstructionHit{k, face, distance_m};
  }
  return best;
}

std::vector<std::array<Vec3, 2>> edges_facing(const ExteriorObstruction& box, const Vec3& point) {
  std::vector<std::array<Vec3, 2>> edges;
  for (int face = 0; face < kBoxFaces; ++face) {
    const int axis = face / 2;
    const bool plus = face % 2 == 1;
    const double plane = plus ? box.max[axis] : box.min[axis];
    if (plus ? !(point[axis] > plane) : !(point[axis] < plane)) continue;
    // The face's four corners in order around it: the other two axes at min / max.
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    std::array<Vec3, 4> c;
    const double us[4] = {box.min[u], box.max[u], box.max[u], box.min[u]};
    const double vs[4] = {box.min[v], box.min[v], box.max[v], box.max[v]};
    for (int i = 0; i < 4; ++i) {
      c[i][axis] = plane, c[i][u] = us[i], c[i][v] = vs[i];
    }
    for (int i = 0; i < 4; ++i) edges.push_back({c[i], c[(i + 1) % 4]});
  }
  return edges;
}

}  // namespace luxgrid::calc
