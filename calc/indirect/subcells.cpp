#include "calc/indirect/subcells.h"

#include <array>
#include <cmath>
#include <map>

#include <tbb/parallel_for.h>

#include "calc/indirect/form_factor.h"

namespace luxgrid::calc::indirect {

SubcellCorners subcell_corners(const Patch& p, int a, int b) {
  const Vec3 o = p.polygon[0];
  const Vec3 e1 = (p.polygon[1] - o) / static_cast<double>(kSubcellsPerSide);
  const Vec3 e2 = (p.polygon[3] - o) / static_cast<double>(kSubcellsPerSide);
  const Vec3 c0 = o + static_cast<double>(a) * e1 + static_cast<double>(b) * e2;
  return {c0, c0 + e1, c0 + e1 + e2, c0 + e2};
}

double subcell_form_factor(const Vec3& x, const Vec3& n, const Patch& p, const SubcellCorners& cell,
                           const Vec3& centre, double cell_area_m2, double near_d2) {
  const Vec3 d = x - centre;
  return glm::dot(d, d) > near_d2 ? point_kernel_form_factor(x, n, centre, p.normal, cell_area_m2)
                                  : point_polygon_form_factor(x, n, cell.data(), 4);
}

CellMesh cell_mesh(const PatchMesh& mesh, const std::vector<char>& refine) {
  CellMesh out;
  out.mesh.patch_size_m = mesh.patch_size_m / kSubcellsPerSide;
  constexpr size_t kCells = kSubcellsPerSide * kSubcellsPerSide;
  // The refined patches in mesh order (rooms are consecutive in the mesh, so their cells are
  // too), then their cells made in parallel, each patch's kCells at their place: a cell's corner
  // list is an allocation of its own, thousands of them touching fresh memory (a page fault a
  // page, docs/performance.md, "Memory"), which one thread alone took milliseconds for.
  std::vector<size_t> refined;
  for (size_t i = 0; i < mesh.patches.size(); ++i)
    if (refine[i] && mesh.patches[i].has_quarters) refined.push_back(i);
  out.mesh.patches.resize(refined.size() * kCells);
  out.patch.resize(refined.size() * kCells);
  tbb::parallel_for(size_t(0), refined.size(), [&](size_t k) {
    const size_t i = refined[k];
    const Patch& p = mesh.patches[i];
    for (int a = 0; a < kSubcellsPerSide; ++a)
      for (int b = 0; b < kSubcellsPerSide; ++b) {
        const size_t at = k * kCells + static_cast<size_t>(a * kSubcellsPerSide + b);
        Patch& c = out.mesh.patches[at];
        c = p;
        const SubcellCorners corners = subcell_corners(p, a, b);
        c.polygon.assign(corners.begin(), corners.end());
        c.centroid = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
        c.area_m2 = p.area_m2 / (kSubcellsPerSide * kSubcellsPerSide);
        c.diameter_m = p.diameter_m / kSubcellsPerSide;
        for (int q = 0; q < 4; ++q) c.quarter_centroid[q] = 0.5 * (corners[q] + c.centroid);
        out.patch[at] = i;
      }
  });
  // Room r's cells: those of its refined patches, [room_begin[r], room_begin[r + 1]).
  size_t k = 0;
  for (size_t r = 0; r + 1 < mesh.room_begin.size(); ++r) {
    while (k < refined.size() && refined[k] < mesh.room_begin[r]) ++k;
    out.mesh.room_begin.push_back(k * kCells);
  }
  out.mesh.room_begin.push_back(out.mesh.patches.size());
  return out;
}

FarCorners far_corners(const PatchMesh& mesh, const CellMesh& cells) {
  constexpr size_t kCells = kSubcellsPerSide * kSubcellsPerSide;
  // Positions in micrometres, normals in millionths: what two patches computed apart from one
  // face's lattice agree on at a shared corner.
  const auto micro = [](double v) { return std::llround(v * 1e6); };
  using Key = std::array<long long, 7>;
  std::map<Key, size_t> index;
  FarCorners out;
  out.of_patch.resize(cells.patch.size() / kCells);
  for (size_t k = 0; k < out.of_patch.size(); ++k) {
    const Patch& p = mesh.patches[cells.patch[k * kCells]];
    for (int c = 0; c < 4; ++c) {
      const Vec3& x = p.polygon[c];
      const Key key{p.room,           micro(x.x),        micro(x.y),
                    micro(x.z),       micro(p.normal.x), micro(p.normal.y),
                    micro(p.normal.z)};
      const auto [at, fresh] = index.try_emplace(key, out.corners.size());
      if (fresh) out.corners.push_back({p.room, x, p.normal});
      out.of_patch[k][c] = at->second;
    }
  }
  return out;
}

double far_corner_weight(int a, int b, int k) {
  const double u = (a + 0.5) / kSubcellsPerSide, v = (b + 0.5) / kSubcellsPerSide;
  switch (k) {
    case 0: return (1 - u) * (1 - v);
    case 1: return u * (1 - v);
    case 2: return u * v;
    default: return (1 - u) * v;
  }
}

SubcellExitance cell_exitance(const PatchMesh& mesh, const CellMesh& cells,
                              const std::vector<double>& exitant_flux_lm,
                              const std::vector<double>& cell_incident_flux_lm,
                              const std::vector<double>& cell_indirect_lx) {
  constexpr int kCells = kSubcellsPerSide * kSubcellsPerSide;
  SubcellExitance out;
  out.first.assign(mesh.patches.size(), -1);
  out.exitance_lm_m2.resize(cells.mesh.patches.size());
  // Cells come kCells at a time, patch by patch (cell_mesh).
  for (size_t c0 = 0; c0 < cells.patch.size(); c0 += kCells) {
    const size_t i = cells.patch[c0];
    const Patch& p = mesh.patches[i];
    const double cell_area = cells.mesh.patches[c0].area_m2;
    double mean_direct = 0.0, mean_indirect = 0.0;
    for (int q = 0; q < kCells; ++q) {
      mean_direct += cell_incident_flux_lm[c0 + q] / cell_area / kCells;
      mean_indirect += cell_indirect_lx[c0 + q] / kCells;
    }
    const double m_patch = exitant_flux_lm[i] / p.area_m2;
    for (int q = 0; q < kCells; ++q) {
      const double e_direct = cell_incident_flux_lm[c0 + q] / cell_area;
      out.exitance_lm_m2[c0 + q] =
          std::max(0.0, m_patch + p.reflectance * (e_direct - mean_direct +
                                                   cell_indirect_lx[c0 + q] - mean_indirect));
    }
    out.first[i] = static_cast<long>(c0);
    ++out.refined_patches;
  }
  return out;
}

}  // namespace luxgrid::calc::indirect
