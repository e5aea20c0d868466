// <surface>.csv: a row per point, and every row says what its E columns measure.
#include <gtest/gtest.h>

#include "report/csv.h"

namespace luxgrid::report {
namespace {

TEST(SurfaceCsv, EveryRowNamesTheQuantity) {
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("seats", {0, 0, 1.2}, {1, 0, 0}, {0, 1, 0}, 1.0, 0.5, 0.5);
  s.grid.quantity = geometry::Quantity::semi_cylindrical;
  for (auto& n : s.grid.normals) n = Vec3(0, -1, 0);  // the facing direction
  s.E_direct = {100.0, 50.0};
  s.E_indirect = {0.0, 0.0};
  s.E = {80.0, 40.0};
  EXPECT_EQ(surface_csv(s),
            "i,j,x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,quantity\n"
            "0,0,0.25,0.25,1.2,0,-1,0,80,100,0,semi-cylindrical\n"
            "1,0,0.75,0.25,1.2,0,-1,0,40,50,0,semi-cylindrical\n");
}

}  // namespace
}  // namespace luxgrid::report
