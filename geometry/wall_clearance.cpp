#include "geometry/wall_clearance.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace luxgrid::geometry {

bool clear_of_walls(const Vec2& p, const Polygon2& poly, double border_m) {
  const double needed_m = border_m - kWallClearanceTolerance_m;
  for (size_t i = 0, n = poly.size(); i < n; ++i) {
    if (distance_to_segment(p, poly[i], poly[(i + 1) % n]) < needed_m) return false;
  }
  return true;
}

namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x * b.y - a.y * b.x; }

// A piece of the boundary the region can have: a wall moved inward by the border (a line from a
// to b), or an arc of the border's radius about a reflex corner, angle phi0 - s sweep (clockwise,
// as the boundary turns there), both for s in [0, 1] and with the region on their left.
struct Piece {
  bool arc = false;
  Vec2 a{0.0}, b{0.0};
  Vec2 centre{0.0};
  double radius_m = 0.0, phi0 = 0.0, sweep = 0.0;
  int skip[3] = {-1, -1, -1};  // walls it cannot come nearer to than the border (see below)

  Vec2 at(double s) const {
    if (!arc) return a + s * (b - a);
    const double phi = phi0 - s * sweep;
    return centre + radius_m * Vec2(std::cos(phi), std::sin(phi));
  }
  double length_m() const { return arc ? radius_m * sweep : glm::length(b - a); }
  bool skips(int wall) const { return skip[0] == wall || skip[1] == wall || skip[2] == wall; }
};

// The parameters where `piece` may cross the boundary of the capsule of radius r about the wall
// from p to q (more than those, never fewer): where it meets the circles about p and q, the two
// lines parallel to the wall at distance r and the two perpendicular lines through p and q. Between
// two consecutive ones the piece lies wholly inside or wholly outside the capsule.
void capsule_crossings(const Piece& piece, const Vec2& p, const Vec2& q, double r,
                       std::vector<double>& out) {
  const double wall_m = glm::length(q - p);
  const Vec2 t = (q - p) / wall_m, n(-t.y, t.x);
  const std::pair<Vec2, double> lines[4] = {{n, r}, {n, -r}, {t, 0.0}, {t, wall_m}};
  if (!piece.arc) {
    const Vec2 d = piece.b - piece.a;
    const double A = glm::dot(d, d);
    for (const Vec2& c : {p, q}) {
      const Vec2 m = piece.a - c;
      const double B = 2.0 * glm::dot(d, m), C = glm::dot(m, m) - r * r;
      const double discriminant = B * B - 4.0 * A * C;
      if (!(discriminant >= 0.0)) continue;
      const double root = std::sqrt(discriminant);
      out.push_back((-B - root) / (2.0 * A));
      out.push_back((-B + root) / (2.0 * A));
    }
    for (const auto& [dir, value] : lines) {
      const double along = glm::dot(dir, d);
      if (along != 0.0) out.push_back((value - glm::dot(dir, piece.a - p)) / along);
    }
    return;
  }
  const double R = piece.radius_m;
  auto add_angle = [&](double phi) {
    double turned = std::fmod(piece.phi0 - phi, kTwoPi);
    if (turned < 0.0) turned += kTwoPi;
    out.push_back(turned / piece.sweep);
  };
  for (const Vec2& c : {p, q}) {
    const Vec2 to_c = c - piece.centre;
    const double D = glm::length(to_c);
    if (D == 0.0) continue;
    const double cos_a = (R * R + D * D - r * r) / (2.0 * R * D);
    if (!(cos_a >= -1.0 && cos_a <= 1.0)) continue;
    const double base = std::atan2(to_c.y, to_c.x), a = std::acos(cos_a);
    add_angle(base + a), add_angle(base - a);
  }
  for (const auto& [dir, value] : lines) {
    // dir . (centre + R (cos phi, sin phi) - p) = value, i.e. cos(phi - psi) = c.
    const double c = (value - glm::dot(dir, piece.centre - p)) / R;
    if (!(c >= -1.0 && c <= 1.0)) continue;
    const double psi = std::atan2(dir.y, dir.x), a = std::acos(c);
    add_angle(psi + a), add_angle(psi - a);
  }
}

// The pieces of the region's boundary candidates in the outline's order: for each corner, its
// arc when it is reflex, then the wall that starts there moved inward.
std::vector<Piece> boundary_pieces(const Polygon2& ccw, double border_m) {
  const size_t n = ccw.size();
  const int count = static_cast<int>(n);
  std::vector<Vec2> normal(n);  // inward (left of the wall's direction)
  std::vector<bool> reflex(n);  // corner k, between wall k - 1 and wall k
  for (size_t k = 0; k < n; ++k) {
    const Vec2 t = glm::normalize(ccw[(k + 1) % n] - ccw[k]);
    normal[k] = Vec2(-t.y, t.x);
  }
  for (size_t k = 0; k < n; ++k) {
    const Vec2 before = ccw[k] - ccw[(k + n - 1) % n], after = ccw[(k + 1) % n] - ccw[k];
    reflex[k] = cross2(before, after) < 0.0;
  }
  std::vector<Piece> pieces;
  for (int k = 0; k < count; ++k) {
    const int prev = (k + count - 1) % count, next = (k + 1) % count;
    if (reflex[k]) {
      // The arc from the end of the previous moved wall to the start of this one. Near its corner
      // both walls lie at exactly the border (the corner is their nearest point): not tested.
      Piece arc;
      arc.arc = true, arc.centre = ccw[k], arc.radius_m = border_m;
      arc.phi0 = std::atan2(normal[prev].y, normal[prev].x);
      const double phi1 = std::atan2(normal[k].y, normal[k].x);
      arc.sweep = std::fmod(arc.phi0 - phi1 + 2.0 * kTwoPi, kTwoPi);
      arc.skip[0] = prev, arc.skip[1] = k;
      if (arc.sweep > 0.0) pieces.push_back(arc);
    }
    // The wall moved inward: its own wall lies at exactly the border, and so does a neighbour
    // across a reflex corner (the outside's wedge there lies wholly beyond this wall's line).
    Piece line;
    line.a = ccw[k] + border_m * normal[k], line.b = ccw[next] + border_m * normal[k];
    line.skip[0] = k;
    if (reflex[k]) line.skip[1] = prev;
    if (reflex[next]) line.skip[2] = next;
    pieces.push_back(line);
  }
  return pieces;
}

struct Part {
  const Piece* piece;
  double s0, s1;
  Vec2 start, end;
};

// The intervals of `piece` that lie at least `border_m` from every wall: [0, 1] less, for each
// wall, the spans between consecutive crossings whose middle lies nearer than the border.
void surviving_parts(const Piece& piece, const Polygon2& ccw, double border_m,
                     std::vector<Part>& out) {
  const size_t n = ccw.size();
  Vec2 lo = glm::min(piece.a, piece.b), hi = glm::max(piece.a, piece.b);
  if (piece.arc) lo = piece.centre - Vec2(piece.radius_m), hi = piece.centre + Vec2(piece.radius_m);
  std::vector<std::pair<double, double>> removed;
  std::vector<double> s;
  for (size_t w = 0; w < n; ++w) {
    if (piece.skips(static_cast<int>(w))) continue;
    const Vec2 &p = ccw[w], &q = ccw[(w + 1) % n];
    // A wall whose box, widened by the border, misses the piece's box cannot come near it.
    const Vec2 wlo = glm::min(p, q) - Vec2(border_m), whi = glm::max(p, q) + Vec2(border_m);
    if (wlo.x > hi.x || wlo.y > hi.y || whi.x < lo.x || whi.y < lo.y) continue;
    s.assign({0.0, 1.0});
    capsule_crossings(piece, p, q, border_m, s);
    std::erase_if(s, [](double v) { return !(v >= 0.0 && v <= 1.0); });
    std::sort(s.begin(), s.end());
    for (size_t j = 0; j + 1 < s.size(); ++j) {
      if (!(s[j + 1] > s[j])) continue;
      const Vec2 mid = piece.at(0.5 * (s[j] + s[j + 1]));
      if (distance_to_segment(mid, p, q) < border_m) removed.emplace_back(s[j], s[j + 1]);
    }
  }
  std::sort(removed.begin(), removed.end());
  // What is left, in order; slivers shorter than the clearance tolerance are rounding.
  const double min_span = kWallClearanceTolerance_m / std::max(piece.length_m(), 1e-300);
  double from = 0.0;
  auto keep = [&](double s0, double s1) {
    if (s1 - s0 > min_span) out.push_back({&piece, s0, s1, piece.at(s0), piece.at(s1)});
  };
  for (const auto& [r0, r1] : removed) {
    if (r0 > from) keep(from, r0);
    from = std::max(from, r1);
  }
  if (from < 1.0) keep(from, 1.0);
}

}  // namespace

std::vector<Polygon2> wall_clearance_region(const Polygon2& ccw, double border_m) {
  const std::vector<Piece> pieces = boundary_pieces(ccw, border_m);
  std::vector<Part> parts;
  for (const Piece& piece : pieces) surviving_parts(piece, ccw, border_m, parts);
  // Chain the parts into closed loops: each part ends where another begins (mathematically the
  // same point, computed from two walls, so up to rounding): take the nearest start.
  std::vector<bool> used(parts.size(), false);
  std::vector<Polygon2> out;
  for (size_t first = 0; first < parts.size(); ++first) {
    if (used[first]) continue;
    std::vector<size_t> loop = {first};
    used[first] = true;
    for (;;) {
      const Vec2 end = parts[loop.back()].end;
      size_t best = first;
      double best_m = glm::length(parts[first].start - end);
      for (size_t j = 0; j < parts.size(); ++j) {
        if (used[j]) continue;
        const double d = glm::length(parts[j].start - end);
        if (d < best_m) best = j, best_m = d;
      }
      if (best == first) break;
      used[best] = true;
      loop.push_back(best);
    }
    Polygon2 poly;
    for (size_t k : loop) {
      const Part& part = parts[k];
      poly.push_back(part.start);
      if (!part.piece->arc) continue;
      const double turn = part.piece->sweep * (part.s1 - part.s0);
      const int steps = static_cast<int>(std::ceil(turn / kArcStep_rad));
      for (int j = 1; j < steps; ++j)
        poly.push_back(part.piece->at(part.s0 + (part.s1 - part.s0) * j / steps));
    }
    if (poly.size() >= 3 && signed_area(poly) > 0.0) out.push_back(std::move(poly));
  }
  return out;
}

}  // namespace luxgrid::geometry
