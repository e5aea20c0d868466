#pragma once
// The working memory of the table rung (table_cubature.cpp): its steps' buffers, grown to the
// largest count seen and kept by the caller between calls, so that a loop over many pairs
// allocates once. Each thread needs its own; calc/direct keeps one per parallel chunk, the
// near/far map one per direction.
#include <vector>

#include "calc/nearfield/table_cells.h"
#include "calc/nearfield/table_psi_cells.h"
#include "calc/nearfield/table_rays.h"

namespace luxgrid::nearfield {

struct TableRungScratch {
  PsiCells psi;
  std::vector<Break> breaks;
  std::vector<RayJob> jobs;
  std::vector<RayEnds> ends;
  std::vector<TableGammaNode> end_nodes;
};

}  // namespace luxgrid::nearfield
