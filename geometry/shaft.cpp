#include "geometry/shaft.h"

#include <algorithm>
#include <cmath>

#include "geometry/occlusion.h"
#include "geometry/polygon.h"

namespace luxgrid::geometry {

namespace {

// Where an element lies relative to a face's plane.
enum class Side { on, above, below, across };

// A point of the shaft's section is this close to the outline (m): kGrazing_m, the rule's own
// boundary tolerance, plus the slack of segment ends and hits computed in double.
constexpr double kOutlineMargin_m = kGrazing_m + 10.0 * kShaftSlack_m;

double turn2(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Convex hull (counter-clockwise, no collinear points) of `p` [Andrew1979, monotone chain], into
// `h`; `p` is sorted and its duplicates removed.
const std::vector<Vec2>& convex_hull(std::vector<Vec2>& p, std::vector<Vec2>& h) {
  std::sort(p.begin(), p.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) {
    h = p;
    return h;
  }
  h.resize(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && turn2(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// The working vectors of one classification.
struct Scratch {
  std::vector<Vec3> corners;
  std::vector<std::pair<size_t, size_t>> edges;
  std::vector<double> h;
  std::vector<Vec2> section, hull;
};

// True when the boxes of two segments (or points) lie more than `gap` apart along x or y: then
// every point of one is farther than `gap` from every point of the other. The tests below ask
// it first with twice their margin, so that the distances they would compute (each within a few
// rounding errors, ~1e-14 m at 100 m) would exceed the margin too: the same answers, fewer
// distances.
bool boxes_apart(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double gap) {
  return std::max(a.x, b.x) + gap < std::min(c.x, d.x) ||
         std::max(c.x, d.x) + gap < std::min(a.x, b.x) ||
         std::max(a.y, b.y) + gap < std::min(c.y, d.y) ||
         std::max(c.y, d.y) + gap < std::min(a.y, b.y);
}

bool segments_within(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, double margin) {
  if (boxes_apart(a, b, c, d, 2.0 * margin)) return false;
  const double d1 = turn2(a, b, c), d2 = turn2(a, b, d), d3 = turn2(c, d, a), d4 = turn2(c, d, b);
  if (((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
      ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)))
    return true;  // proper crossing
  return std::min({distance_to_segment(a, c, d), distance_to_segment(b, c, d),
                   distance_to_segment(c, a, b), distance_to_segment(d, a, b)}) <= margin;
}

// True when `p` lies in the convex counter-clockwise polygon `q` grown by `margin`.
bool in_convex(const Vec2& p, const std::vector<Vec2>& q, double margin) {
  if (q.size() < 3) {
    if (q.size() == 1) return glm::length(p - q[0]) <= margin;
    return distance_to_segment(p, q[0], q[1]) <= margin;
  }
  for (size_t i = 0; i < q.size(); ++i) {
    const Vec2& a = q[i];
    const Vec2& b = q[(i + 1) % q.size()];
    if (turn2(a, b, p) < -margin * glm::length(b - a)) return false;
  }
  return true;
}

// True when the segment ab comes within `margin` of the convex polygon `q` (hull order).
bool segment_meets_convex(const Vec2& a, const Vec2& b, const std::vector<Vec2>& q, double margin) {
  if (in_convex(a, q, margin) || in_convex(b, q, margin)) return true;
  if (q.size() == 1) return distance_to_segment(q[0], a, b) <= margin;
  for (size_t i = 0; i < q.size(); ++i)
    if (segments_within(a, b, q[i], q[(i + 1) % q.size()], margin)) return true;
  return false;
}

// True when some outline edge comes within `margin` of the convex section `q`.
bool outline_meets(const Polygon2& outline, const std::vector<Vec2>& q, double margin) {
  for (size_t i = 0; i < outline.size(); ++i)
    if (segment_meets_convex(outline[i], outline[(i + 1) % outline.size()], q, margin)) return true;
  return false;
}

// Index pairs of an element whose segments include every edge of its convex hull: consecutive
// corners of a planar convex polygon, every pair otherwise.
void hull_edges(std::span<const Vec3> e, size_t offset,
                std::vector<std::pair<size_t, size_t>>& out) {
  const size_t n = e.size();
  bool convex_polygon = n > 3;
  if (convex_polygon) {
    Vec3 normal(0.0);  // Newell's normal
    for (size_t i = 0; i < n; ++i) normal += glm::cross(e[i], e[(i + 1) % n]);
    const double area2 = glm::length(normal);
    convex_polygon = area2 > 0.0;
    for (size_t i = 0; convex_polygon && i < n; ++i) {
      const Vec3 turn = glm::cross(e[(i + 1) % n] - e[i], e[(i + 2) % n] - e[(i + 1) % n]);
      // Every turn the same way round and the corners in one plane: a convex polygon.
      convex_polygon = glm::dot(turn, normal) >= 0.0 &&
                       glm::length(glm::cross(turn, normal)) <= 1e-9 * area2 * glm::length(turn);
    }
  }
  if (convex_polygon) {
    for (size_t i = 0; i < n; ++i) out.emplace_back(offset + i, offset + (i + 1) % n);
    return;
  }
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) out.emplace_back(offset + i, offset + j);
}

}  // namespace

ShaftClassifier::ShaftClassifier(const std::vector<Face>& faces) {
  for (size_t i = 0; i < faces.size(); ++i) {
    const Face& f = faces[i];
    if (f.corners.size() < 3) continue;
    Candidate c;
    c.face = static_cast<uint32_t>(i);
    c.sheet = face_sheet(f);
    c.box.lo = c.box.hi = f.corners.front();
    for (const Vec3& p : f.corners)
      c.box.lo = glm::min(c.box.lo, p), c.box.hi = glm::max(c.box.hi, p);
    const Vec3& n = c.sheet.normal;
    for (int k = 0; k < 3; ++k)
      if (n[(k + 1) % 3] == 0.0 && n[(k + 2) % 3] == 0.0) c.axis = k;
    faces_.push_back(std::move(c));
  }
}

size_t box_element(const Vec3& lo, const Vec3& hi, const Vec3& shift, std::array<Vec3, 8>& out) {
  int free_axes[3], count = 0;
  for (int k = 0; k < 3; ++k)
    if (hi[k] > lo[k]) free_axes[count++] = k;
  // Corner c of the box: bit i of c chooses hi along the i-th free axis.
  const auto corner = [&](int c) {
    Vec3 p = lo;
    for (int i = 0; i < count; ++i)
      if (c >> i & 1) p[free_axes[i]] = hi[free_axes[i]];
    return p + shift;
  };
  if (count == 2) {  // round the rectangle, not in bit order
    const int round[4] = {0, 1, 3, 2};
    for (int i = 0; i < 4; ++i) out[i] = corner(round[i]);
    return 4;
  }
  const int corners = 1 << count;
  for (int c = 0; c < corners; ++c) out[c] = corner(c);
  return static_cast<size_t>(corners);
}

Shaft ShaftClassifier::classify(std::span<const Vec3> a, std::span<const Vec3> b) const {
  ShaftFaces undecided;
  return classify(a, b, ShaftFaces{}, undecided);
}

Shaft ShaftClassifier::classify(std::span<const Vec3> a, std::span<const Vec3> b,
                                const ShaftFaces& among, ShaftFaces& undecided) const {
  // `among` may be `undecided` itself: the faces left are gathered here first.
  ShaftFaces left;
  left.count = 0;
  const auto done = [&](Shaft verdict) {
    undecided = verdict == Shaft::partial ? left : ShaftFaces{};
    return verdict;
  };
  if (a.empty() || b.empty()) return done(Shaft::partial);
  // Scratch kept per thread: a verdict is asked millions of times (calc/indirect's gather asks
  // one per receiver and chunk), and four fresh vectors each time cost more than the tests.
  thread_local Scratch scratch;
  std::vector<Vec3>& corners = scratch.corners;
  corners.assign(a.begin(), a.end());
  corners.insert(corners.end(), b.begin(), b.end());
  Box3 shaft{corners.front(), corners.front()};
  for (const Vec3& p : corners) shaft.lo = glm::min(shaft.lo, p), shaft.hi = glm::max(shaft.hi, p);
  // Every segment is at most this long, so the rule shortens it by at least this fraction at
  // each end.
  const double length_m = glm::length(shaft.hi - shaft.lo);
  const double least_shortening = kOcclusionEndAllowance_m / std::max(length_m, 1e-300);
  // An element this far off a plane keeps every shortened end off it, however the other element
  // lies within kShaftSlack_m of the plane.
  const double off_plane_m = std::max(4.0 * kShaftSlack_m / least_shortening, kShaftSlack_m);
  std::vector<std::pair<size_t, size_t>>& edges = scratch.edges;
  edges.clear();
  hull_edges(a, 0, edges);
  hull_edges(b, a.size(), edges);
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j) edges.emplace_back(i, a.size() + j);
  const double reach = kOutlineMargin_m + kShaftSlack_m;
  std::vector<double>& h = scratch.h;
  h.resize(corners.size());
  std::vector<Vec2>& section = scratch.section;
  bool partial = false;
  const size_t candidates = among.narrowed() ? static_cast<size_t>(among.count) : faces_.size();
  for (size_t i = 0; i < candidates; ++i) {
    const uint32_t k = among.narrowed() ? among.face[i] : static_cast<uint32_t>(i);
    const Candidate& c = faces_[k];
    bool apart = false;
    for (int k = 0; k < 3; ++k)
      apart = apart || shaft.hi[k] < c.box.lo[k] - reach || shaft.lo[k] > c.box.hi[k] + reach;
    if (apart) continue;
    const FaceSheet& f = c.sheet;
    // A plane normal to an axis: the rule's heights are exact differences of one coordinate
    // (the other products are zeros), and rounding is monotone, so an element touching the
    // plane from the side of the other cannot give the rule heights of opposite signs.
    if (c.axis >= 0) {
      bool up = true, down = true;
      for (const Vec3& p : corners) {
        up = up && p[c.axis] >= f.origin[c.axis];
        down = down && p[c.axis] <= f.origin[c.axis];
      }
      if (up || down) continue;
    }
    const auto side = [&](size_t begin, size_t end) {
      bool on = true, above = true, below = true;
      for (size_t i = begin; i < end; ++i) {
        on = on && std::abs(h[i]) <= kShaftSlack_m;
        above = above && h[i] >= off_plane_m;
        below = below && h[i] <= -off_plane_m;
      }
      return on ? Side::on : above ? Side::above : below ? Side::below : Side::across;
    };
    for (size_t i = 0; i < corners.size(); ++i) h[i] = glm::dot(corners[i] - f.origin, f.normal);
    const Side sa = side(0, a.size()), sb = side(a.size(), corners.size());
    // Both within kShaftSlack_m of the plane: every segment grazes it (kGrazing_m). One on it,
    // the other off it, or both on one side: the shortened ends never lie on opposite sides.
    if ((sa != Side::below && sa != Side::across && sb != Side::below && sb != Side::across) ||
        (sa != Side::above && sa != Side::across && sb != Side::above && sb != Side::across))
      continue;
    // Where the rule's hits can lie: the shaft within kShaftSlack_m of the plane (a hit is on its
    // segment and within rounding of the plane), seen in the face's frame.
    section.clear();
    const auto add = [&](const Vec3& p) {
      section.emplace_back(glm::dot(p - f.origin, f.u), glm::dot(p - f.origin, f.v));
    };
    for (size_t i = 0; i < corners.size(); ++i)
      if (std::abs(h[i]) <= kShaftSlack_m) add(corners[i]);
    for (const auto& [i, j] : edges)
      for (const double level : {-kShaftSlack_m, kShaftSlack_m}) {
        const double hl = h[i] - level, hr = h[j] - level;
        if ((hl < 0.0 && hr > 0.0) || (hl > 0.0 && hr < 0.0))
          add(corners[i] + (corners[j] - corners[i]) * (hl / (hl - hr)));
      }
    if (section.empty()) continue;
    // The section's box against the outline's box, before the exact tests below: apart by the
    // margin, the shaft passes beside the face; on a rectangle, a section well inside it is
    // crossed by every segment from one side to the other (what the exact tests would find).
    Vec2 qlo = section.front(), qhi = section.front();
    for (const Vec2& p : section) qlo = glm::min(qlo, p), qhi = glm::max(qhi, p);
    if (qhi.x < c.sheet.outline_lo.x - kOutlineMargin_m ||
        qlo.x > c.sheet.outline_hi.x + kOutlineMargin_m ||
        qhi.y < c.sheet.outline_lo.y - kOutlineMargin_m ||
        qlo.y > c.sheet.outline_hi.y + kOutlineMargin_m)
      continue;
    const bool across =
        (sa == Side::above && sb == Side::below) || (sa == Side::below && sb == Side::above);
    if (c.sheet.rectangle && across && qlo.x > c.sheet.outline_lo.x + kOutlineMargin_m &&
        qhi.x < c.sheet.outline_hi.x - kOutlineMargin_m &&
        qlo.y > c.sheet.outline_lo.y + kOutlineMargin_m &&
        qhi.y < c.sheet.outline_hi.y - kOutlineMargin_m)
      return done(Shaft::hidden);
    const std::vector<Vec2>& q = convex_hull(section, scratch.hull);
    bool inside = true, touches = false;
    for (const Vec2& p : q) {
      // Beyond the outline's box by twice the margin: outside, as locate() would say.
      const Location where =
          boxes_apart(p, p, c.sheet.outline_lo, c.sheet.outline_hi, 2.0 * kOutlineMargin_m)
              ? Location::outside
              : locate(p, f.outline, kOutlineMargin_m);
      inside = inside && where == Location::inside;
      touches = touches || where != Location::outside;
    }
    const bool edge_meets = outline_meets(f.outline, q, kOutlineMargin_m);
    if (!touches && !edge_meets) continue;  // the shaft passes beside the face
    // Every segment from one side to the other, crossing well inside the outline.
    if (inside && !edge_meets && across) return done(Shaft::hidden);
    partial = true;
    // Past kMaxFaces the shaft is not narrowed: every face stays a candidate.
    if (left.narrowed() && left.count < ShaftFaces::kMaxFaces)
      left.face[static_cast<size_t>(left.count++)] = k;
    else
      left.count = -1;
  }
  return done(partial ? Shaft::partial : Shaft::visible);
}

}  // namespace luxgrid::geometry
