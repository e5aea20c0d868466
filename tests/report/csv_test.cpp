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
  s.E_indirect = {0.0, 0.0};
  s.E = {80.0, 40.0};
  s.E_direct = {80.0, 40.0};
  EXPECT_EQ(surface_csv(s),
            "i,j,x,y,z,nx,ny,nz,active,E_maintained_lx,E_direct_maintained_lx,E_indirect_"
            "maintained_lx,quantity\n"
            "0,0,0.25,0.25,1.2,0,-1,0,true,80,80,0,semi-cylindrical\n"
            "1,0,0.75,0.25,1.2,0,-1,0,true,40,40,0,semi-cylindrical\n");
}

TEST(SurfaceCsv, PointsLeftOutSayActiveFalseAndHaveNoIlluminance) {
  // A spreadsheet's MIN and AVERAGE skip empty cells: over the E column they give the
  // statistics luxgrid computes over the active points (here Emin 40, Eavg 60), not 0 and 40.
  calc::SurfaceResult s;
  s.grid = geometry::make_plane_grid("wp", {0, 0, 0.8}, {1, 0, 0}, {0, 1, 0}, 1.5, 0.5, 0.5);
  s.grid.active = {true, false, true};
  s.E_direct = {80.0, 0.0, 30.0};
  s.E_indirect = {0.0, 0.0, 10.0};
  s.E = {80.0, 0.0, 40.0};
  EXPECT_EQ(surface_csv(s),
            "i,j,x,y,z,nx,ny,nz,active,E_maintained_lx,E_direct_maintained_lx,E_indirect_"
            "maintained_lx,quantity\n"
            "0,0,0.25,0.25,0.8,0,0,1,true,80,80,0,planar\n"
            "1,0,0.75,0.25,0.8,0,0,1,false,,,,planar\n"
            "2,0,1.25,0.25,0.8,0,0,1,true,40,30,10,planar\n");
}

}  // namespace
}  // namespace luxgrid::report
