#include "calc/indirect/prism_visibility.h"

namespace luxgrid::calc::indirect {

OcclusionFn prism_occlusion(const Room& room) {
  return [outline = room.outline](const Vec3& a, const Vec3& b) {
    const Vec2 p(a.x, a.y), q(b.x, b.y);
    for (size_t k = 0, n = outline.size(); k < n; ++k)
      if (segments_cross(p, q, outline[k], outline[(k + 1) % n])) return true;
    // A segment may also leave through a re-entrant vertex without properly crossing an edge:
    // test its midpoint (both ends are inside or on the boundary).
    const Vec2 mid = 0.5 * (p + q);
    return !point_in_polygon(outline, mid) && distance_to_boundary(outline, mid) > 1e-9;
  };
}

}  // namespace luxgrid::calc::indirect
