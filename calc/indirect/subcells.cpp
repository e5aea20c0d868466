#include "calc/indirect/subcells.h"

namespace luxgrid::calc::indirect {

SubcellCorners subcell_corners(const Patch& p, int a, int b) {
  const Vec3 o = p.polygon[0];
  const Vec3 e1 = (p.polygon[1] - o) / static_cast<double>(kSubcellsPerSide);
  const Vec3 e2 = (p.polygon[3] - o) / static_cast<double>(kSubcellsPerSide);
  const Vec3 c0 = o + static_cast<double>(a) * e1 + static_cast<double>(b) * e2;
  return {c0, c0 + e1, c0 + e1 + e2, c0 + e2};
}

CellMesh cell_mesh(const PatchMesh& mesh, const std::vector<char>& refine) {
  CellMesh out;
  out.mesh.patch_size_m = mesh.patch_size_m / kSubcellsPerSide;
  // Reserved at once: thousands of cells grown by doubling would touch twice their memory for
  // the first time, a page fault a page (docs/performance.md, "Memory touched for the first time").
  const auto refined = [&](size_t i) { return refine[i] && mesh.patches[i].has_quarters; };
  size_t cells = 0;
  for (size_t i = 0; i < mesh.patches.size(); ++i)
    cells += refined(i) ? kSubcellsPerSide * kSubcellsPerSide : 0;
  out.mesh.patches.reserve(cells);
  out.patch.reserve(cells);
  for (size_t r = 0; r + 1 < mesh.room_begin.size(); ++r) {
    out.mesh.room_begin.push_back(out.mesh.patches.size());
    for (size_t i = mesh.room_begin[r]; i < mesh.room_begin[r + 1]; ++i) {
      if (!refined(i)) continue;
      const Patch& p = mesh.patches[i];
      for (int a = 0; a < kSubcellsPerSide; ++a)
        for (int b = 0; b < kSubcellsPerSide; ++b) {
          Patch c = p;
          const SubcellCorners corners = subcell_corners(p, a, b);
          c.polygon.assign(corners.begin(), corners.end());
          c.centroid = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
          c.area_m2 = p.area_m2 / (kSubcellsPerSide * kSubcellsPerSide);
          c.diameter_m = p.diameter_m / kSubcellsPerSide;
          for (int q = 0; q < 4; ++q) c.quarter_centroid[q] = 0.5 * (corners[q] + c.centroid);
          out.mesh.patches.push_back(std::move(c));
          out.patch.push_back(i);
        }
    }
  }
  out.mesh.room_begin.push_back(out.mesh.patches.size());
  return out;
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
