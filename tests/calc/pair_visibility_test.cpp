// The direct light's use of shaft culling (geometry/pair_visibility.h in calc/direct.cpp): in an
// L-shaped room with obstacles, each luminaire-point pair computed through the pair's verdict
// equals, bit for bit, the pair computed with the occlusion test per quadrature node, at every
// quality's near model and the automatic switch; and the verdict does serve most pairs.
#include <gtest/gtest.h>

#include <cstdio>

#include "../nearfield/nearfield_test_support.h"
#include "calc/nearfield/illuminance.h"
#include "geometry/occlusion.h"
#include "geometry/pair_visibility.h"

namespace luxgrid::calc {
namespace {

using nearfield::Model;

TEST(PairVisibility, DirectLightIsIdenticalWithAndWithoutTheShaftVerdict) {
  const geometry::Polygon2 l = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};
  auto faces = geometry::room_faces(geometry::RoomShape{"L", l, 0.0, 3.0, 0.2, 0.5, 0.7});
  for (const auto& o : {geometry::make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.35, 0.4),
                        geometry::make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5)}) {
    const auto f = geometry::obstacle_faces(o);
    faces.insert(faces.end(), f.begin(), f.end());
  }
  const geometry::OcclusionTree tree(faces);
  // 0.6 x 0.6 m openings on the ceiling in both legs, facing down.
  std::vector<nearfield::Emitter> emitters;
  for (const Vec3& at : {Vec3(1.5, 4.5, 3.0), Vec3(4.5, 1.0, 3.0), Vec3(2.5, 2.5, 3.0)}) {
    photometry::LuminousOpening o;
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = o.width = 0.6;
    emitters.push_back(
        nearfield::make_emitter(o, at, glm::dmat3(1.0), nearfield::testing::batwing()));
  }
  size_t served = 0, pairs = 0, hidden = 0;
  // `reference` on every fourth lattice point (it costs about 20 times `high`).
  for (const Model& model : {Model::standard(), Model::high(), Model::reference(1e-3)})
    for (const auto& e : emitters)
      for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
          if (model.kind == nearfield::ModelKind::reference && (i % 2 != 0 || j % 2 != 0)) continue;
          const Vec3 p(0.5 * i, 0.5 * j, (i + j) % 3 == 0 ? 0.0 : 0.75);
          if (p.x > 3 && p.y > 3) continue;
          const Vec3 up(0, 0, 1);
          const double plain = nearfield::hybrid_illuminance(
              e, p, up, model, nearfield::NearFieldSwitch::automatic, &tree);
          const geometry::PairVisibility shaft(tree, e.vertices, std::span<const Vec3>(&p, 1));
          const double culled = nearfield::hybrid_illuminance(
              e, p, up, model, nearfield::NearFieldSwitch::automatic, &shaft);
          ASSERT_EQ(plain, culled) << p.x << " " << p.y << " " << p.z;
          ++pairs;
          if (shaft.verdict() != geometry::Shaft::partial) ++served;
          hidden += shaft.verdict() == geometry::Shaft::hidden ? 1 : 0;
        }
  // Not vacuous: the verdict serves many pairs, hidden ones among them.
  std::printf("pairs %zu, served by the verdict %zu (hidden %zu)\n", pairs, served, hidden);
  EXPECT_GT(served, pairs / 4) << pairs;
  EXPECT_GT(hidden, 10u);
}

}  // namespace
}  // namespace luxgrid::calc
