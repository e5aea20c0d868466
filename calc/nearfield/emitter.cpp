#include "calc/nearfield/emitter.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "calc/nearfield/fixed_rule.h"
#include "util/error.h"

namespace luxgrid::nearfield {
namespace {

// Newell's normal of a polygon: twice the vector area.
Vec3 vector_area2(const std::vector<Vec3>& v) {
  Vec3 sum{0.0};
  for (std::size_t i = 0; i < v.size(); ++i) sum += glm::cross(v[i], v[(i + 1) % v.size()]);
  return sum;
}

}  // namespace

Emitter make_polygon_emitter(std::vector<Vec3> vertices, const glm::dmat3& rotation,
                             photometry::DistributionPtr distribution,
                             std::shared_ptr<const TableGammaCells> table_cells) {
  if (!distribution) throw InputError("near-field emitter: no intensity distribution");
  if (vertices.size() > static_cast<std::size_t>(kMaxPolygonVertices - 2))
    throw InputError("near-field emitter: " + std::to_string(vertices.size()) +
                     " vertices, at most " + std::to_string(kMaxPolygonVertices - 2));
  Emitter e;
  e.rotation = rotation;
  e.world_to_local = glm::transpose(rotation);
  e.normal = glm::normalize(rotation * Vec3(0.0, 0.0, -1.0));
  e.distribution = std::move(distribution);
  if (const photometry::TableView view = e.distribution->table_view(); view.table)
    e.table_cells = table_cells ? std::move(table_cells) : make_table_gamma_cells(*view.table);
  Vec3 c{0.0};
  for (const Vec3& v : vertices) c += v;
  if (!vertices.empty()) c /= static_cast<double>(vertices.size());
  e.centroid = c;
  double diameter = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (std::size_t j = i + 1; j < vertices.size(); ++j)
      diameter = std::max(diameter, glm::length(vertices[i] - vertices[j]));
  e.largest_dimension_m = diameter;
  if (vertices.size() >= 3) {
    // Relative to the centroid so that a 1 km offset does not eat the digits of a 1 mm polygon.
    std::vector<Vec3> rel(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) rel[i] = vertices[i] - c;
    const Vec3 a2 = vector_area2(rel);
    // Counter-clockwise seen from the emitting side: Newell normal along the emitting normal.
    if (glm::dot(a2, e.normal) < 0.0) std::reverse(vertices.begin(), vertices.end());
    e.area_m2 = 0.5 * std::abs(glm::dot(a2, e.normal));
    for (const Vec3& r : rel)
      if (std::abs(glm::dot(r, e.normal)) > 1e-9 * std::max(diameter, 1e-300))
        throw InputError("near-field emitter: polygon is not flat in the plane of its normal");
    // The centroid of the area (not of the vertices) for the far-field point.
    Vec3 ac{0.0};
    double a_sum = 0.0;
    for (std::size_t i = 1; i + 1 < rel.size(); ++i) {
      const double a = 0.5 * glm::dot(glm::cross(rel[i] - rel[0], rel[i + 1] - rel[0]), e.normal);
      ac += a * (rel[0] + rel[i] + rel[i + 1]) / 3.0;
      a_sum += a;
    }
    if (std::abs(a_sum) > 0.0) e.centroid = c + ac / a_sum;
  }
  e.vertices = std::move(vertices);
  if (e.vertices.size() >= 3) {
    std::vector<Vec3> local;
    for (const Vec3& v : e.vertices) {
      Vec3 l = e.world_to_local * (v - e.centroid);
      l.z = 0.0;  // in the plane to rounding (checked above)
      local.push_back(l);
    }
    const FixedRule rule = make_fixed_rule(local, e.largest_dimension_m);
    for (const Vec3& n : rule.nodes_local) e.rule_nodes.push_back(e.centroid + e.rotation * n);
    e.rule_weights = rule.weights;
  }
  return e;
}

Emitter make_emitter(const photometry::LuminousOpening& opening, const Vec3& position,
                     const glm::dmat3& rotation, photometry::DistributionPtr distribution,
                     int disk_segments, std::shared_ptr<const TableGammaCells> table_cells) {
  using Shape = photometry::LuminousOpening::Shape;
  if (opening.length < 0.0 || opening.width < 0.0)
    throw InputError("near-field emitter: negative opening size " + std::to_string(opening.length) +
                     " x " + std::to_string(opening.width) + " m");
  std::vector<Vec3> local;
  switch (opening.shape) {
    case Shape::point: local.push_back(Vec3(0.0)); break;
    case Shape::rectangle: {
      const double hx = 0.5 * opening.length, hy = 0.5 * opening.width;
      if (hx == 0.0 || hy == 0.0) {
        local.push_back(Vec3(0.0));
        break;
      }
      local = {{hx, hy, 0.0}, {-hx, hy, 0.0}, {-hx, -hy, 0.0}, {hx, -hy, 0.0}};
      break;
    }
    case Shape::disk: {
      if (disk_segments < 3 || disk_segments > kMaxDiskSegments)
        throw InputError("near-field emitter: disk_segments " + std::to_string(disk_segments) +
                         " outside 3.." + std::to_string(kMaxDiskSegments));
      // Diameter along x is `length`, along y `width` (an ellipse if they differ; 0 = same).
      const double dx = opening.length;
      const double dy = opening.width > 0.0 ? opening.width : opening.length;
      if (dx == 0.0 || dy == 0.0) {
        local.push_back(Vec3(0.0));
        break;
      }
      // Area-preserving N-gon: area of the inscribed N-gon is (N/2) sin(2 pi/N) r^2.
      const double n = disk_segments;
      const double scale = std::sqrt(kPi / (0.5 * n * std::sin(2.0 * kPi / n)));
      for (int i = 0; i < disk_segments; ++i) {
        const double t = 2.0 * kPi * i / n;
        local.push_back({0.5 * dx * scale * std::cos(t), 0.5 * dy * scale * std::sin(t), 0.0});
      }
      break;
    }
  }
  std::vector<Vec3> world;
  world.reserve(local.size());
  for (const Vec3& l : local) world.push_back(position + rotation * l);
  Emitter e = make_polygon_emitter(std::move(world), rotation, std::move(distribution),
                                   std::move(table_cells));
  if (e.is_point()) e.centroid = position;
  return e;
}

}  // namespace luxgrid::nearfield
