#pragma once
// The fixed rule: a low-order cubature of the area form over the opening, for near-field pairs
// far enough away that the opening's footprint covers only a few table cells
// (docs/nearfield.md, "The fixed rule"). The opening is cut by a grid of at most
// kFixedRuleMaxCells x kFixedRuleMaxCells cells; each cell's part of the polygon is one node
// at its centroid, weighted by its share of the area: E = sum_j (a_j / A) I(w_j) g(u_j) / d_j^2.
// The centroid rule is exact for a linear integrand on each cell, so across a kink of the table
// (the far field's trouble, falling only as 1 / d) the error is the slope change times the
// cell's share of the footprint squared: about kFixedRuleMaxCells^2 times smaller than the far
// field's. The error is not assumed: far_field_bound.cpp measures it per direction against the
// quality's rung, and the run uses the rule only beyond that distance.
#include <vector>

#include "geometry/visibility.h"
#include "util/robust_math.h"

namespace luxgrid::nearfield {

struct Emitter;
struct Receiver;

// Cells per largest dimension D of the opening, and at most per axis: a 0.6 m square gets
// 3 x 3 nodes, a 1.2 x 0.2 m linear opening 4 x 1. Four per D puts a node every quarter of the
// footprint; more nodes cost more than the near rung saves at the distances where the rule is
// then within the promise (measured on the open-plan example, docs/accuracy.md).
inline constexpr double kFixedRuleCellsPerD = 4.0;
inline constexpr int kFixedRuleMaxCells = 4;

struct FixedRule {
  std::vector<Vec3> nodes_local;  // m, luminaire frame relative to the centroid (z = 0)
  std::vector<double> weights;    // share of the area, sum 1
};

// The rule for a flat convex polygon given in the luminaire frame relative to its centroid
// (z = 0), of largest dimension `largest_dimension_m`. Empty for fewer than 3 vertices.
FixedRule make_fixed_rule(const std::vector<Vec3>& polygon_local, double largest_dimension_m);

// Illuminance (lx) by the emitter's fixed rule (Emitter::rule_nodes), finite and >= 0; with an
// occluder each node is tested (soft shadows at the rule's resolution).
double fixed_rule_illuminance(const Emitter& e, const Vec3& point, const Receiver& receiver,
                              const geometry::Visibility* occluder = nullptr);

}  // namespace luxgrid::nearfield
