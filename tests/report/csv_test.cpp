// <surface>.csv: a row per point, and every row says what its E columns measure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

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

TEST(SurfaceCsv, NumbersAreWrittenAsPrintfsSixSignificantDigits) {
  // The CSV writes numbers as printf's "%.6g" does (docs/project-format.md): fixed or exponent
  // form by the exponent, trailing zeros dropped, "-0" kept. Checked cell by cell against
  // snprintf over magnitudes from 1e-310 to 1e300, both signs, the zeros and rounding ties.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-310.0, 300.0), mantissa(1.0, 10.0);
  std::vector<double> values = {0.0,  -0.0,        1.0,      0.5, 999999.5, 9999995.0,
                                1e-5, 1.234565e-4, 123456.5, 0.1, 1e16};
  for (int k = 0; k < 3000; ++k)
    values.push_back((k % 2 ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, exponent(rng)));
  calc::SurfaceResult s;
  s.grid.name = "values";
  for (size_t k = 0; k + 2 < values.size(); k += 3) {
    s.grid.points.emplace_back(values[k], values[k + 1], values[k + 2]);
    s.grid.normals.emplace_back(values[k + 2], values[k], values[k + 1]);
    s.E.push_back(values[k + 1]);
    s.E_direct.push_back(values[k + 2]);
    s.E_indirect.push_back(values[k]);
  }
  const std::string csv = surface_csv(s);
  std::string expected = std::string(kSurfaceCsvHeader) + "\n";
  char line[512];
  for (size_t k = 0; k < s.grid.points.size(); ++k) {
    const auto& p = s.grid.points[k];
    const auto& n = s.grid.normals[k];
    std::snprintf(line, sizeof line,
                  "0,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,true,%.6g,%.6g,%.6g,planar\n", k, p.x, p.y,
                  p.z, n.x, n.y, n.z, s.E[k], s.E_direct[k], s.E_indirect[k]);
    expected += line;
  }
  EXPECT_EQ(csv, expected);
}

}  // namespace
}  // namespace luxgrid::report
