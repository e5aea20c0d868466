#include "calc/indirect/first_bounce.h"

#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <tbb/parallel_for.h>

#include "calc/indirect/emitter_cells.h"
#include "calc/scaled_distribution.h"
#include "geometry/box3.h"
#include "geometry/spherical.h"
#include "geometry/triangle_solid_angles4.h"

namespace luxgrid::calc::indirect {

using geometry::box_distance2;

namespace {

// A luminaire closer than this to a patch's plane sends it no light (grazing or behind); it also
// keeps the solid angle of a patch the luminaire sits on (a recessed downlight) from being 2 pi.
constexpr double kMinPlaneDistance_m = 1e-6;
// Sample points are lifted this far off the face before visibility tests, so that a segment
// ending on a wall is not reported as crossing it.
constexpr double kSampleLift_m = 1e-6;
constexpr int kMaxLevel = 6;
// Once a patch's pieces disagree on visibility, integrate it this many levels deeper (the
// shadow edge is then resolved to 1/4 of the piece size per extra level... 1/2 per level).
constexpr int kShadowExtraLevels = 2;

// One cell of a luminaire's opening (emitter_cells.h): a point source of weight x the
// luminaire's intensity.
struct Source {
  Vec3 position{0.0};
  const Luminaire* lum = nullptr;
  double weight = 1.0;
  const photometry::IntensityDistribution* intensity = nullptr;  // the luminaire's lookup
};

struct Sampler {
  const Source& src;
  const geometry::Visibility* visibility;  // null: nothing blocks
  Vec3 normal;
  mutable int visible = 0, hidden = 0;

  double triangle(const Vec3& a, const Vec3& b, const Vec3& c, int level) const {
    if (level > 0) {
      const Vec3 ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
      if (level > 1)
        return triangle(a, ab, ca, level - 1) + triangle(ab, b, bc, level - 1) +
               triangle(ca, bc, c, level - 1) + triangle(ab, bc, ca, level - 1);
      // The four halves are the pieces: their solid angles at once, added in the same order.
      double t[4];
      leaves({a, ab, ca, ab}, {ab, b, bc, bc}, {ca, bc, c, ca}, t);
      return t[0] + t[1] + t[2] + t[3];
    }
    return leaf(a, b, c, geometry::triangle_solid_angle_from(src.position, a, b, c));
  }
  // Four pieces: their solid angles in the lanes of one computation
  // (geometry/triangle_solid_angles4.h), visibility and intensity one by one.
  void leaves(const Vec3 (&a)[4], const Vec3 (&b)[4], const Vec3 (&c)[4], double (&t)[4]) const {
    double omega[4];
    geometry::triangle_solid_angles_from4(src.position, a, b, c, omega);
    for (int k = 0; k < 4; ++k) t[k] = leaf(a[k], b[k], c[k], omega[k]);
  }
  // One piece of solid angle omega: I towards its centre x omega, unless the centre is hidden.
  double leaf(const Vec3& a, const Vec3& b, const Vec3& c, double omega) const {
    const Vec3 s = src.position;
    const Vec3 centre = (a + b + c) / 3.0;
    if (geometry::blocked(visibility, s, centre + normal * kSampleLift_m)) {
      ++hidden;
      return 0.0;
    }
    ++visible;
    const Vec3 dir = glm::normalize(centre - s);
    const Vec3 local = glm::transpose(src.lum->pose.rotation) * dir;
    return src.weight * src.intensity->intensity(local) * omega;
  }
};

// Solid angle (sr) of a convex planar polygon seen from s, in front of it: the fan of triangles
// from its first corner, each by Van Oosterom-Strackee (tan(omega / 2) = numerator /
// denominator), added as the arguments of the complex numbers denominator + i numerator, so one
// atan2 serves the whole polygon. The sum of the half angles is below pi (a polygon seen from
// one side spans less than 2 pi), so the product's argument is the sum.
double convex_polygon_solid_angle_from(const Vec3& s, const Polygon3& polygon) {
  const size_t n = polygon.size();
  if (n < 3) return 0.0;
  std::array<Vec3, 16> u_small;
  std::vector<Vec3> u_large;
  Vec3* u = u_small.data();
  if (n > u_small.size()) u_large.resize(n), u = u_large.data();
  for (size_t k = 0; k < n; ++k) {
    const Vec3 r = polygon[k] - s;
    const double len = glm::length(r);
    if (!(len > 0.0)) return 0.0;
    u[k] = r / len;
  }
  double re = 1.0, im = 0.0;
  for (size_t k = 1; k + 1 < n; ++k) {
    const Vec3 &a = u[0], &b = u[k], &c = u[k + 1];
    const double num = std::abs(glm::dot(a, glm::cross(b, c)));
    const double den = 1.0 + glm::dot(a, b) + glm::dot(a, c) + glm::dot(b, c);
    const double r2 = re * den - im * num, i2 = re * num + im * den;
    re = r2, im = i2;
  }
  return 2.0 * std::atan2(im, re);
}

double patch_flux(const Source& src, const Patch& p, const geometry::Visibility* visibility,
                  double max_angle_rad, bool one_piece) {
  const Vec3 s = src.position;
  const double h = glm::dot(p.normal, s - p.centroid);
  if (!(h > kMinPlaneDistance_m)) return 0.0;
  // Distance from the luminaire to the nearest point of the patch is at least h; use the
  // centroid distance less the radius for the angular size of the whole patch.
  const double dist = std::max(h, glm::length(s - p.centroid) - 0.5 * p.diameter_m);
  const double angle = p.diameter_m / dist;
  int level = 0;
  // Each fan triangle spans about half the patch; each level halves a piece.
  while (level < kMaxLevel && 0.5 * angle / std::ldexp(1.0, level) > max_angle_rad) ++level;
  if (one_piece && level == 0 && !visibility) {
    // The whole patch as one piece: its exact solid angle times I towards its centroid (the
    // midpoint rule of the integral of I over the patch's solid angle, whose pieces here span
    // at most 2 max_angle_rad). The solid angles stay exact, so a closed room still receives the
    // emitted flux to the quadrature error of I alone.
    const Vec3 dir = glm::normalize(p.centroid - s);
    const Vec3 local = glm::transpose(src.lum->pose.rotation) * dir;
    return src.weight * src.intensity->intensity(local) *
           convex_polygon_solid_angle_from(s, p.polygon);
  }
  Sampler sampler{src, visibility, p.normal};
  auto integrate = [&](int lv) {
    double flux = 0.0;
    const size_t n = p.polygon.size();
    if (lv == 0 && n == 4) {  // the fan's four triangles are the pieces
      const Polygon3& q = p.polygon;
      const Vec3 o = p.centroid;
      double t[4];
      sampler.leaves({o, o, o, o}, {q[0], q[1], q[2], q[3]}, {q[1], q[2], q[3], q[0]}, t);
      for (int k = 0; k < 4; ++k) flux += t[k];
      return flux;
    }
    for (size_t k = 0; k < n; ++k)
      flux += sampler.triangle(p.centroid, p.polygon[k], p.polygon[(k + 1) % n], lv);
    return flux;
  };
  double flux = integrate(level);
  if (visibility && sampler.visible > 0 && sampler.hidden > 0) {
    sampler.visible = sampler.hidden = 0;
    flux = integrate(std::min(kMaxLevel, level + kShadowExtraLevels));
  }
  return flux;
}

// Tiles of a room's patches for tiled_first_bounce: runs of consecutive coplanar patches (a face)
// cut into squares of kTile x the run's largest diameter, in the face's own coordinates
// (origin, u, v), with each patch's coordinates.
constexpr double kTile = 4.0;
// A patch whose diameter over its distance from the source is below 0.03 (squared here) takes
// the point form of its solid angle in tiled_first_bounce.
constexpr double kPointSolidAngle2 = 0.03 * 0.03;
struct Tile {
  std::vector<size_t> patches;
  std::vector<double> pu, pv;  // the patches' centroids in (u, v)
  Vec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  Vec3 origin{0.0}, u{0.0}, v{0.0}, normal{0.0};
  double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0;
};

std::vector<Tile> face_tiles(const PatchMesh& mesh, size_t begin, size_t end) {
  std::vector<Tile> tiles;
  for (size_t k = begin; k < end;) {
    const Patch& first = mesh.patches[k];
    size_t e = k + 1;
    double dmax = first.diameter_m;
    while (e < end && mesh.patches[e].normal == first.normal &&
           std::abs(glm::dot(first.normal, mesh.patches[e].centroid - first.centroid)) < 1e-9)
      dmax = std::max(dmax, mesh.patches[e++].diameter_m);
    const Vec3 u = glm::normalize(first.polygon[1] - first.polygon[0]);
    const Vec3 v = glm::cross(first.normal, u);
    const double tile = kTile * dmax;
    std::map<std::pair<long, long>, size_t> index;
    for (size_t i = k; i < e; ++i) {
      const Patch& p = mesh.patches[i];
      const double pu = glm::dot(p.centroid - first.centroid, u);
      const double pv = glm::dot(p.centroid - first.centroid, v);
      const auto key = std::make_pair(static_cast<long>(std::floor(pu / tile)),
                                      static_cast<long>(std::floor(pv / tile)));
      auto [it, fresh] = index.try_emplace(key, tiles.size());
      if (fresh) {
        tiles.emplace_back();
        tiles.back().origin = first.centroid, tiles.back().u = u, tiles.back().v = v;
        tiles.back().normal = first.normal;
      }
      Tile& t = tiles[it->second];
      t.patches.push_back(i), t.pu.push_back(pu), t.pv.push_back(pv);
      t.u0 = std::min(t.u0, pu), t.u1 = std::max(t.u1, pu);
      t.v0 = std::min(t.v0, pv), t.v1 = std::max(t.v1, pv);
      for (const auto& c : p.polygon) t.lo = glm::min(t.lo, c), t.hi = glm::max(t.hi, c);
    }
    k = e;
  }
  return tiles;
}

// The first bounce of a room where nothing blocks, tile by tile. A source on or behind a tile's
// plane sends it nothing (the ceiling, for ceiling-mounted luminaires: no patch is visited). A
// tile seen under at most 2 max_angle_rad takes the source's intensity at its four corners (in
// the face's coordinates) and each patch the bilinear interpolation at its centroid, times the
// patch's solid angle (exact, or A h / d^3 for a patch seen under less than 0.03 rad): four
// intensity look-ups for the tile's 16 patches, with an error of second order in the tile's
// angular size (the interpolation's), as the one-piece rule of patch_flux has in the patch's.
// Other tiles: patch_flux per patch (one piece where it is far).
void tiled_first_bounce(const std::vector<Source>& sources, const PatchMesh& mesh, size_t begin,
                        size_t end, double max_angle_rad, std::vector<double>& incident_flux_lm) {
  const std::vector<Tile> tiles = face_tiles(mesh, begin, end);
  const double far2 = 4.0 * max_angle_rad * max_angle_rad;
  tbb::parallel_for(size_t(0), tiles.size(), [&](size_t t) {
    const Tile& tile = tiles[t];
    const size_t count = tile.patches.size();
    std::vector<double> sum(count, 0.0);
    const double diagonal2 = glm::dot(tile.hi - tile.lo, tile.hi - tile.lo);
    for (const Source& src : sources) {
      const Vec3 s = src.position;
      if (!(glm::dot(tile.normal, s - tile.origin) > kMinPlaneDistance_m)) continue;
      if (count < 4 || !(diagonal2 <= far2 * box_distance2(s, tile.lo, tile.hi))) {
        for (size_t k = 0; k < count; ++k)
          sum[k] += patch_flux(src, mesh.patches[tile.patches[k]], nullptr, max_angle_rad, true);
        continue;
      }
      const auto to_local = glm::transpose(src.lum->pose.rotation);
      const auto intensity_at = [&](double a, double b) {
        const Vec3 dir = glm::normalize(tile.origin + a * tile.u + b * tile.v - s);
        return src.weight * src.intensity->intensity(to_local * dir);
      };
      const double i00 = intensity_at(tile.u0, tile.v0), i10 = intensity_at(tile.u1, tile.v0);
      const double i01 = intensity_at(tile.u0, tile.v1), i11 = intensity_at(tile.u1, tile.v1);
      const double du = tile.u1 - tile.u0, dv = tile.v1 - tile.v0;
      for (size_t k = 0; k < count; ++k) {
        const Patch& p = mesh.patches[tile.patches[k]];
        const double h = glm::dot(p.normal, s - p.centroid);
        if (!(h > kMinPlaneDistance_m)) continue;
        const double a = du > 0.0 ? (tile.pu[k] - tile.u0) / du : 0.0;
        const double b = dv > 0.0 ? (tile.pv[k] - tile.v0) / dv : 0.0;
        const double i =
            (1 - a) * (1 - b) * i00 + a * (1 - b) * i10 + (1 - a) * b * i01 + a * b * i11;
        const Vec3 r = p.centroid - s;
        const double d2 = glm::dot(r, r);
        // Seen under less than kPointSolidAngle: the solid angle A h / d^3 (no atan2), whose
        // relative error is about (D / d)^2 / 8, 1.1e-4 at the switch; closer, the exact one.
        const double omega = p.diameter_m * p.diameter_m < kPointSolidAngle2 * d2
                                 ? p.area_m2 * h / (d2 * std::sqrt(d2))
                                 : convex_polygon_solid_angle_from(s, p.polygon);
        sum[k] += i * omega;
      }
    }
    for (size_t k = 0; k < count; ++k) incident_flux_lm[tile.patches[k]] = sum[k];
  });
}

}  // namespace

FirstBounce first_bounce(
    const Scene& scene, const PatchMesh& mesh,
    const std::vector<const geometry::Visibility*>& visibility, double max_angle_rad,
    const std::map<const photometry::IntensityDistribution*, double>* known_flux_lm,
    const std::map<const photometry::IntensityDistribution*, photometry::DistributionPtr>*
        intensity_lookup,
    const std::vector<char>* one_piece_rooms) {
  FirstBounce fb;
  const size_t n = mesh.patches.size();
  fb.incident_flux_lm.assign(n, 0.0);
  fb.vpl_flux_lm.assign(n, 0.0);
  // luminous_flux integrates the whole distribution: once per distinct distribution (the
  // members of an array share theirs), not once per luminaire.
  std::map<const photometry::IntensityDistribution*, double> flux_of;
  if (known_flux_lm) flux_of = *known_flux_lm;
  // The sources of each room (the cells of the luminaires' openings inside it, in scene
  // order)...
  std::vector<std::vector<Source>> in_room(scene.rooms.size());
  for (const auto& lum : scene.luminaires) {
    const std::vector<RoomCells> parts = emitter_cells(scene, lum);
    if (parts.empty()) {
      IndirectNote note;
      note.kind = IndirectNote::Kind::luminaire_outside;
      note.luminaire = lum.label;
      fb.notes.push_back(std::move(note));
      continue;
    }
    auto [it, fresh] = flux_of.try_emplace(lum.distribution.get(), 0.0);
    if (fresh) it->second = luminous_flux(*lum.distribution);
    fb.luminaire_flux_lm += it->second;
    const photometry::IntensityDistribution* intensity = lum.distribution.get();
    if (intensity_lookup) {
      const auto found = intensity_lookup->find(intensity);
      if (found != intensity_lookup->end() && found->second) intensity = found->second.get();
    }
    for (const RoomCells& part : parts) {
      fb.emitted_flux_lm += part.weight * it->second;
      for (const EmitterCell& cell : part.cells)
        in_room[part.room].push_back({cell.position, &lum, cell.weight, intensity});
    }
    if (auto note = outside_note(lum, parts, scene, it->second)) fb.notes.push_back(*note);
  }
  // ...then one parallel loop over the patches, each adding its room's luminaires in that order
  // (one loop instead of one per luminaire; the same sums).
  for (size_t r = 0; r < scene.rooms.size(); ++r) {
    if (in_room[r].empty()) continue;
    const geometry::Visibility* room_visibility = visibility[r];
    const bool one_piece = one_piece_rooms && (*one_piece_rooms)[r];
    if (one_piece && !room_visibility) {
      tiled_first_bounce(in_room[r], mesh, mesh.room_begin[r], mesh.room_begin[r + 1],
                         max_angle_rad, fb.incident_flux_lm);
      continue;
    }
    tbb::parallel_for(mesh.room_begin[r], mesh.room_begin[r + 1], [&](size_t i) {
      double sum = 0.0;
      for (const Source& src : in_room[r])
        sum += patch_flux(src, mesh.patches[i], room_visibility, max_angle_rad, one_piece);
      fb.incident_flux_lm[i] = sum;
    });
  }
  add_reflected_flux(mesh, fb);
  return fb;
}

void add_reflected_flux(const PatchMesh& mesh, FirstBounce& fb) {
  const size_t n = mesh.patches.size();
  fb.vpl_flux_lm.assign(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    fb.vpl_flux_lm[i] = mesh.patches[i].reflectance * fb.incident_flux_lm[i];
    fb.received_flux_lm += fb.incident_flux_lm[i];
    if (fb.vpl_flux_lm[i] > 0.0) ++fb.vpl_count;
  }
}

}  // namespace luxgrid::calc::indirect
