// The table rung (docs/nearfield.md, "The table rung"): the area form of the illuminance
//   E = (1/A) integral over the clipped polygon of I(C, gamma) cos_r / d^2 dA
// in polar coordinates around the receiver's foot F on the emitter plane.
//
// Why polar around F: seen from an emitter point y, the receiver x lies at photometric angles
// gamma = angle between the emitter's axis and (x - y), C = azimuth of (x - y). With y at
// in-plane offset rho (cos psi, sin psi) from F and sigma the receiver's signed distance from
// the plane, gamma' = atan(rho / |sigma|) is gamma (front) or pi - gamma (back) and C = psi + pi.
// So the table's C lines are rays from F and its gamma lines are circles around F: the cells
// of (psi, gamma') between them are exactly the table's cells, inside which a bilinear
// (bicubic) interpolant is smooth. The adaptive rungs sample across those kinks and their error
// indicators misjudge them (docs/accuracy.md); here every kink is a cell boundary and a
// 2 x 2 Gauss-Legendre rule per cell converges like on a smooth function.
//
// The measure: dA / d^2 = rho d rho d psi / d^2 = tan(gamma') d gamma' d psi, and
// cos_r = sin(gamma') (n_x cos psi + n_y sin psi) + sign(sigma) n_z cos(gamma') with n the
// receiver normal in the luminaire frame. tan(gamma') grows without bound towards the plane
// (gamma' -> 90 deg); cells there are split so tan grows by at most kTableTanRatio across each
// (table_cells.h).
//
// Other receivers (receiver_kernel.h): the unit direction to a node is
// u = sin(gamma') a + cos(gamma') axis in the world, a = R (cos psi, sin psi, 0) per ray and
// axis = sign(sigma) R (0, 0, 1), and receiver_weight(receiver, u) replaces cos_r. For a cylinder
// the weight sin(eps) / pi is smooth on the cells except at the one node direction straight up or
// down, where its cone vertex (weight 0) sits; there the integrand is small, so the cell rule's
// error stays far below the rung's tolerance (tests/nearfield/cylindrical_test.cpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "calc/nearfield/fan_sample.h"
#include "calc/nearfield/models.h"
#include "calc/nearfield/receiver_fan.h"
#include "calc/nearfield/receiver_kernel.h"
#include "calc/nearfield/table_cells.h"
#include "calc/nearfield/table_polygon.h"
#include "calc/nearfield/table_psi_cells.h"
#include "calc/nearfield/table_rays.h"
#include "calc/nearfield/table_rung_scratch.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::nearfield {
namespace {

// A plane receiver whose normal (unit, luminaire frame) leans off the emitter's axis by at most
// this much in x and y is integrated in closed form along each ray with the radial term of cos_r
// left out: it contributes at most this times sin(gamma') tan(gamma') of the integrand, a relative
// 1e-12 x tan(gamma') (below 1e-9 for every gamma' short of 89.9 degrees). Rotations by multiples
// of 90 degrees leave components of ~1e-16.
constexpr double kAxialNormalTolerance = 1e-12;

// The closed form along rays (RayIntegrals::closed_ray): a bilinear table and a plane normal
// (unit, luminaire frame) along the axis.
bool closed_form_applies(const photometry::TabularDistribution& table, const Vec3& n_local) {
  return table.interpolation() == photometry::Interpolation::bilinear &&
         std::abs(n_local.x) <= kAxialNormalTolerance &&
         std::abs(n_local.y) <= kAxialNormalTolerance;
}

// The rung's last step: the integral along each ray, from its ends, for one receiver (or the
// light vector's moments), the table read at the ray's C position.
class RayIntegrals {
 public:
  RayIntegrals(const Emitter& e, const photometry::TabularDistribution& table,
               const TableGammaCells& cells, const Receiver& receiver, bool front, bool closed_form,
               std::vector<TableGammaNode>& end_nodes)
      : e_(e),
        table_(table),
        cells_(cells),
        receiver_(receiver),
        front_(front),
        planar_(receiver.kind == ReceiverKind::planar),
        closed_form_(closed_form),
        n_(e.world_to_local * receiver.direction),
        n_z_(front ? n_.z : -n_.z),
        axis_((front ? 1.0 : -1.0) * e.rotation[2]),
        end_nodes_(end_nodes) {}

  // The integral along ray r (lux x area before the table's scale: sum over rays of
  // job.scale x this), or with `moments` its light vector's moments added there. The lines
  // strictly inside each ray's range of table angles: a ray's ends cross a line only where that
  // line's circle crosses the outline, a psi break, so the rays of a cell have the same (found
  // for the first ray that reaches the opening, reused for the others: `lines_cell`). Where an
  // end lies within rounding of a line, another ray's end may lie a rounding past it: its end
  // piece then spans a signed sliver of the neighbouring interval, the same integral up to
  // rounding.
  void integrate(const RayJob* jobs, const RayEnds* ends, std::size_t count, double& sum,
                 Vec3* moments_sum) {
    const std::vector<double>& lines = cells_.lines;
    std::size_t k_lo = 0, k_hi = 0, lines_cell = std::numeric_limits<std::size_t>::max();
    for (std::size_t r = 0; r < count; ++r) {
      const RayEnds& end = ends[r];
      if (!end.ok) continue;
      const RayJob& job = jobs[r];
      const double cp = job.c, sp = job.s;
      const double t_lo = front_ ? end.g_near : kPi - end.g_far,
                   t_hi = front_ ? end.g_far : kPi - end.g_near;
      const double c = first_copy_at_or_above(job.psi + kPi, 0.0);
      const photometry::TabularDistribution::CCell& cc = job.c_cell;
      const photometry::TabularDistribution::CPosition cpos =
          c >= cc.c0 && c <= cc.c1 ? table_.c_position_in(cc, c) : table_.c_position(c);
      const double tan_lo = front_ ? end.tan_near : end.tan_far,
                   tan_hi = front_ ? end.tan_far : end.tan_near;
      // Lines strictly inside (t_lo, t_hi): [k_lo, k_hi).
      if (job.cell != lines_cell) {
        k_lo = cells_.first_above(t_lo), k_hi = cells_.first_at_or_above(t_hi);
        lines_cell = job.cell;
      }
      if (moments_sum) {
        Moments m;
        if (k_lo >= k_hi) {
          end_moments(t_lo, t_hi, tan_lo, tan_hi, cpos, m);
        } else {
          end_moments(t_lo, lines[k_lo], tan_lo, cells_.line_tan[k_lo], cpos, m);
          end_moments(lines[k_hi - 1], t_hi, cells_.line_tan[k_hi - 1], tan_hi, cpos, m);
          const TableGammaNode* base = cells_.nodes.data();
          add_moments(base + cells_.first[k_lo], base + cells_.first[k_hi - 1], cpos, m);
        }
        *moments_sum += job.scale * Vec3(m.radial * cp, m.radial * sp, front_ ? m.axial : -m.axial);
        continue;
      }
      double ray = 0.0;
      if (closed_form_) {
        ray = closed_ray(t_lo, t_hi, end.sin_near, end.cos_near, end.sin_far, end.cos_far, k_lo,
                         k_hi, cpos);
      } else if (const Ray dir{n_.x * cp + n_.y * sp, cp * e_.rotation[0] + sp * e_.rotation[1]};
                 k_lo >= k_hi) {
        ray = end_cell(t_lo, t_hi, tan_lo, tan_hi, cpos, dir);
      } else {
        ray = end_cell(t_lo, lines[k_lo], tan_lo, cells_.line_tan[k_lo], cpos, dir) +
              end_cell(lines[k_hi - 1], t_hi, cells_.line_tan[k_hi - 1], tan_hi, cpos, dir);
        // The whole cells between: nodes precomputed per emitter (table_cells.h).
        const TableGammaNode* base = cells_.nodes.data();
        ray += node_sum(base + cells_.first[k_lo], base + cells_.first[k_hi - 1], cpos, dir);
      }
      sum += job.scale * ray;
    }
  }

 private:
  using CPosition = photometry::TabularDistribution::CPosition;
  // One ray's direction terms: `radial` = n . (cos psi, sin psi, 0) in the luminaire frame for a
  // plane, `a` = R (cos psi, sin psi, 0) for any other receiver.
  struct Ray {
    double radial;
    Vec3 a;
  };
  // The light vector: per ray the nodes' moments sum_j w_j I_j (sin, cos) of gamma', no receiver
  // weight and no clamp (the caller's plane sees the whole opening, so cos_r > 0 at every node).
  struct Moments {
    double radial = 0.0, axial = 0.0;
  };

  // The nodes of one ray: weight x receiver weight (cos_r for a plane) x intensity, the table
  // read with the ray's C position. Any other receiver: the world direction to a node is
  // sin(gamma') a + cos(gamma') axis.
  double node_sum(const TableGammaNode* q, const TableGammaNode* end, const CPosition& c,
                  const Ray& ray) const {
    double v = 0.0;
    for (; q != end; ++q) {
      const double g = planar_
                           ? q->sin_g * ray.radial + n_z_ * q->abs_cos_g
                           : receiver_weight(receiver_, q->sin_g * ray.a + q->abs_cos_g * axis_);
      if (!(g > 0.0) || q->row < 0) continue;
      v += q->weight_tan * g * table_.intensity_at(c, static_cast<std::size_t>(q->row), q->tg);
    }
    return v;
  }
  // One end cell of a ray: table angles [a, b] with |tan| ta, tb, nodes computed here.
  double end_cell(double a, double b, double ta, double tb, const CPosition& c, const Ray& ray) {
    end_nodes_.clear();
    append_gamma_nodes(table_, a, b, ta, tb, end_nodes_);
    return node_sum(end_nodes_.data(), end_nodes_.data() + end_nodes_.size(), c, ray);
  }
  // One ray in closed form: table angles [t_lo, t_hi] (the ray's in-plane reach rho_min,
  // rho_max), the lines strictly inside are [k_lo, k_hi).
  double closed_ray(double t_lo, double t_hi, double sin_near, double cos_near, double sin_far,
                    double cos_far, std::size_t k_lo, std::size_t k_hi, const CPosition& c) const {
    const std::vector<double>& lines = cells_.lines;
    const double* gamma_rows = table_.grid().gamma_rad.data();
    const long* interval_row = cells_.interval_row.data();
    const double* inv_row_width = cells_.inv_row_width.data();
    const std::size_t line_count = lines.size();
    // sin and cos of the table angles at the ray's ends (of gamma' at its near and far end).
    const double s_lo = front_ ? sin_near : sin_far, s_hi = front_ ? sin_far : sin_near;
    const double c_lo = front_ ? cos_near : -cos_far, c_hi = front_ ? cos_far : -cos_near;
    const photometry::TabularDistribution::CColumns columns = table_.c_columns(c);
    // The piece [a, b] of interval k (k < 0 or past the last line: outside the table).
    const auto piece = [&](long k, double a, double sa, double ca, double b, double sb, double cb) {
      if (k < 0 || static_cast<std::size_t>(k) >= line_count) return 0.0;
      const long row = interval_row[k];
      if (row < 0) return 0.0;
      const std::size_t j = static_cast<std::size_t>(row);
      return linear_sin_integral(a, sa, ca, b, sb, cb, gamma_rows[j], inv_row_width[j],
                                 columns.row_value(j), columns.row_value(j + 1));
    };
    const long first = static_cast<long>(k_lo) - 1;
    if (k_lo >= k_hi) return n_z_ * piece(first, t_lo, s_lo, c_lo, t_hi, s_hi, c_hi);
    double v =
        piece(first, t_lo, s_lo, c_lo, lines[k_lo], cells_.line_sin[k_lo], cells_.line_cos[k_lo]) +
        piece(static_cast<long>(k_hi) - 1, lines[k_hi - 1], cells_.line_sin[k_hi - 1],
              cells_.line_cos[k_hi - 1], t_hi, s_hi, c_hi);
    if (k_lo + 1 < k_hi) v += cells_.whole_intervals(c, k_lo, k_hi - 1);
    return n_z_ * v;
  }
  void add_moments(const TableGammaNode* q, const TableGammaNode* end, const CPosition& c,
                   Moments& m) const {
    for (; q != end; ++q) {
      if (q->row < 0) continue;
      const double wi =
          q->weight_tan * table_.intensity_at(c, static_cast<std::size_t>(q->row), q->tg);
      m.radial += wi * q->sin_g;
      m.axial += wi * q->abs_cos_g;
    }
  }
  void end_moments(double a, double b, double ta, double tb, const CPosition& c, Moments& m) {
    end_nodes_.clear();
    append_gamma_nodes(table_, a, b, ta, tb, end_nodes_);
    add_moments(end_nodes_.data(), end_nodes_.data() + end_nodes_.size(), c, m);
  }

  const Emitter& e_;
  const photometry::TabularDistribution& table_;
  const TableGammaCells& cells_;
  const Receiver& receiver_;
  const bool front_, planar_, closed_form_;
  const Vec3 n_;      // the receiver's normal in the luminaire frame (a plane)
  const double n_z_;  // its component towards the opening
  const Vec3 axis_;   // sign(sigma) R (0, 0, 1) in the world
  std::vector<TableGammaNode>& end_nodes_;
};

}  // namespace

bool table_rung_in_closed_form(const Emitter& e, const Vec3& normal) {
  const photometry::TableView view =
      e.distribution ? e.distribution->table_view() : photometry::TableView{};
  if (!view.table || e.is_point() || !e.table_cells || e.table_cells->table != view.table)
    return false;
  return closed_form_applies(*view.table, e.world_to_local * normal);
}

bool table_aligned_illuminance(const Emitter& e, const Vec3& point, const Vec3& normal, double& lux,
                               TableRungScratch& scratch) {
  return table_aligned_illuminance(e, point, Receiver::planar(normal), lux, scratch);
}

namespace {

// The rung for one receiver (light_vector null: `lux`), or the light vector of the whole opening
// in the luminaire frame, unscaled (light_vector set: the receiver is not used). Its steps, each
// a loop of independent iterations over the rays (the rays' ends are a long chain of dependent
// operations, determinant, square root, division, table angle, and a loop that does only them
// lets the processor run several rays' chains at once): the psi cells (psi_cells), their rays
// (cell_rays), the rays' ends (ray_ends), the integrals along the rays (RayIntegrals).
bool table_rung(const Emitter& e, const Vec3& point, const Receiver& receiver, double& lux,
                Vec3* light_vector, TableRungScratch& scratch) {
  const photometry::TableView view =
      e.distribution ? e.distribution->table_view() : photometry::TableView{};
  if (!view.table || e.is_point() || !e.table_cells || e.table_cells->table != view.table)
    return false;
  lux = 0.0;
  if (light_vector) *light_vector = Vec3(0.0);
  const ShiftedReceiver shifted = shift_off_emitter_plane(e, point, horizon_shift_m(e));
  const OpeningPolygon clipped =
      clip_to_horizon(e, shifted.point, light_vector ? Vec3(0.0) : receiver.horizon_normal());
  if (clipped.n < 3) return true;

  // Luminaire frame, origin at the (shifted) receiver: a vertex's x, y are its offset from F,
  // its z is sigma (the same for all, up to rounding).
  Polygon2 poly;
  poly.n = clipped.n;
  double sigma = 0.0, reach2 = 0.0;
  for (int i = 0; i < clipped.n; ++i) {
    const Vec3 q = e.world_to_local * clipped.v[i];
    poly.v[i] = glm::dvec2(q.x, q.y);
    sigma += q.z;
    reach2 = std::max(reach2, glm::dot(poly.v[i], poly.v[i]));
  }
  sigma /= clipped.n;
  poly.prepare_edges();
  const double abs_sigma = std::abs(sigma);
  if (!(abs_sigma > 0.0)) return true;  // excluded by the horizon shift
  const bool front = sigma > 0.0;
  const double inv_sigma = 1.0 / abs_sigma;
  const photometry::TabularDistribution& table = *view.table;
  const TableGammaCells& cells = *e.table_cells;

  const bool inside = contains_origin(poly);
  if (!psi_cells(poly, inside, front, abs_sigma, std::sqrt(reach2), cells, table.grid().c_rad,
                 scratch.psi, scratch.breaks))
    return true;
  // A plane facing the axis (a workplane under a ceiling luminaire, the floor, the ceiling) on a
  // bilinear table: cos_r = n_z cos(gamma'), so along a ray the integrand is n_z I(C, gamma)
  // sin(gamma'), and I is linear in gamma inside each table cell: the gamma integral is exact in
  // closed form (linear_sin_integral), no nodes, no trigonometry but the ray's end angles.
  // Whole intervals read their weights from table_cells.h. Normals off the axis by more than
  // kAxialNormalTolerance keep the nodes (the radial term sin^2 / cos has no elementary integral
  // against a linear I).
  const bool planar = receiver.kind == ReceiverKind::planar;
  const Vec3 n = e.world_to_local * receiver.direction;
  const double n_z = front ? n.z : -n.z;
  const bool closed_form = !light_vector && planar && closed_form_applies(table, n);
  if (closed_form && !(n_z > 0.0)) return true;  // the receiver faces away: cos_r <= 0 everywhere
  // The cells' rays, with what a cell's rays share: with F outside, the edges they enter and
  // leave through (no vertex direction lies inside a cell), and the table's C cell (nor does a
  // C plane). The loops index the buffers through plain pointers and counts.
  const std::size_t ray_count = cell_rays(poly, scratch.psi, table, scratch.jobs);
  if (scratch.ends.size() < ray_count) scratch.ends.resize(ray_count);
  const RayJob* const jobs = scratch.jobs.data();
  RayEnds* const ends = scratch.ends.data();
  // Each ray's reach [rho_min, rho_max] and the sines, cosines and table angles at its ends.
  ray_ends(poly, inside, inv_sigma, jobs, ray_count, ends);
  // The integral along each ray that reaches the opening, added in the rays' order.
  double sum = 0.0;
  Vec3 moments_sum(0.0);
  RayIntegrals(e, table, cells, receiver, front, closed_form, scratch.end_nodes)
      .integrate(jobs, ends, ray_count, sum, light_vector ? &moments_sum : nullptr);
  if (light_vector) *light_vector = (view.scale / e.area_m2) * moments_sum;
  lux = sanitize_illuminance(view.scale * sum / e.area_m2);
  return true;
}

}  // namespace

bool table_aligned_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                               double& lux, TableRungScratch& scratch) {
  return table_rung(e, point, receiver, lux, nullptr, scratch);
}

bool table_light_vector(const Emitter& e, const Vec3& point, Vec3& light_vector_lx,
                        TableRungScratch& scratch) {
  double unused = 0.0;
  Vec3 local(0.0);
  if (!table_rung(e, point, Receiver::planar(Vec3(0, 0, 1)), unused, &local, scratch)) return false;
  light_vector_lx = e.rotation * local;
  return true;
}

}  // namespace luxgrid::nearfield
