// The direct light's use of shaft culling (geometry/pair_visibility.h in calc/direct.cpp): in an
// L-shaped room with obstacles, each luminaire-point pair computed through the pair's verdict
// equals, bit for bit, the pair computed with the occlusion test per quadrature node, at every
// quality's near model and the automatic switch; and the verdict does serve most pairs. And
// quality reference with narrowed shafts (calc/nearfield/area_reference.cpp: each triangle of the
// adaptive cubature classified within its parent's undecided faces, its nodes answered from what
// it leaves, geometry/visibility.h ShaftFaces) equals, bit for bit, the same integration with one
// traced segment per node and no classification at all; and the narrowed faces answer its nodes.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>

#include "../nearfield/nearfield_test_support.h"
#include "calc/nearfield/illuminance.h"
#include "geometry/occlusion.h"
#include "geometry/pair_visibility.h"

namespace luxgrid::calc {
namespace {

using nearfield::Model;

// An L-shaped room with `obstacles`, its occlusion test.
geometry::OcclusionTree l_room(const std::vector<geometry::Obstacle>& obstacles) {
  const geometry::Polygon2 l = {{0, 0}, {6, 0}, {6, 3}, {3, 3}, {3, 6}, {0, 6}};
  auto faces = geometry::room_faces(geometry::RoomShape{"L", l, 0.0, 3.0, 0.2, 0.5, 0.7});
  for (const auto& o : obstacles) {
    const auto f = geometry::obstacle_faces(o);
    faces.insert(faces.end(), f.begin(), f.end());
  }
  return geometry::OcclusionTree(faces);
}

// 0.6 x 0.6 m openings on the ceiling in both legs and over the cabinet, facing down.
std::vector<nearfield::Emitter> ceiling_openings() {
  std::vector<nearfield::Emitter> emitters;
  for (const Vec3& at : {Vec3(1.5, 4.5, 3.0), Vec3(4.5, 1.0, 3.0), Vec3(2.5, 2.5, 3.0)}) {
    photometry::LuminousOpening o;
    o.shape = photometry::LuminousOpening::Shape::rectangle;
    o.length = o.width = 0.6;
    emitters.push_back(
        nearfield::make_emitter(o, at, glm::dmat3(1.0), nearfield::testing::batwing()));
  }
  return emitters;
}

TEST(PairVisibility, DirectLightIsIdenticalWithAndWithoutTheShaftVerdict) {
  const geometry::OcclusionTree tree =
      l_room({geometry::make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.35, 0.4),
              geometry::make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5)});
  const std::vector<nearfield::Emitter> emitters = ceiling_openings();
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
          // `standard` and `high` ask the pair's verdict before their rungs (illuminance.cpp
          // pair_verdict), so a decided pair never reaches the wrapper's own; either way it is
          // the same shaft's.
          const geometry::Shaft verdict = tree.classify(e.vertices, std::span<const Vec3>(&p, 1));
          if (verdict != geometry::Shaft::partial) ++served;
          hidden += verdict == geometry::Shaft::hidden ? 1 : 0;
        }
  // Not vacuous: a verdict decides many pairs, hidden ones among them.
  std::printf("pairs %zu, decided by a verdict %zu (hidden %zu)\n", pairs, served, hidden);
  EXPECT_GT(served, pairs / 4) << pairs;
  EXPECT_GT(hidden, 10u);
}

// The occlusion test segment by segment: no verdicts, no narrowing (the interface's defaults).
class RayByRay final : public geometry::Visibility {
 public:
  explicit RayByRay(const geometry::Visibility& exact) : exact_(exact) {}
  bool visible(const Vec3& from, const Vec3& to) const override { return exact_.visible(from, to); }

 private:
  const geometry::Visibility& exact_;
};

// The scene's test as it is, counting the nodes answered from narrowed faces.
class Counting final : public geometry::Visibility {
 public:
  explicit Counting(const geometry::Visibility& exact) : exact_(exact) {}
  bool visible(const Vec3& from, const Vec3& to) const override { return exact_.visible(from, to); }
  geometry::Shaft classify(std::span<const Vec3> a, std::span<const Vec3> b) const override {
    return exact_.classify(a, b);
  }
  geometry::Shaft classify_within(std::span<const Vec3> a, std::span<const Vec3> b,
                                  const geometry::ShaftFaces& among,
                                  geometry::ShaftFaces& undecided) const override {
    return exact_.classify_within(a, b, among, undecided);
  }
  bool visible_among(const Vec3& from, const Vec3& to,
                     const geometry::ShaftFaces& faces) const override {
    ++(faces.narrowed() ? narrowed : whole);
    return exact_.visible_among(from, to, faces);
  }
  mutable std::atomic<size_t> narrowed{0}, whole{0};

 private:
  const geometry::Visibility& exact_;
};

TEST(PairVisibility, ReferenceDirectLightIsIdenticalToTracingEveryNode) {
  const geometry::OcclusionTree tree =
      l_room({geometry::make_box("cabinet", {1, 1, 0}, {2, 2, 1.8}, 0.35, 0.4),
              geometry::make_box("column", {4, 1, 0}, {5, 2, 3}, 0.0, 0.5),
              geometry::make_box("desk", {1, 4, 0.7}, {2.5, 5, 0.75}, 0.0, 0.5)});
  const RayByRay rays(tree);
  const Counting counting(tree);
  const std::vector<nearfield::Emitter> emitters = ceiling_openings();
  // At 10x reference's tolerance (a tenth of the cost, the same shadow edges) on a 1 m lattice of
  // the floor and the desk's height, plus the points beside the reflex corner and the obstacles
  // where shadows fall.
  std::vector<Vec3> points;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j)
      if (!(i > 3 && j > 3)) points.emplace_back(i, j, (i + j) % 2 == 0 ? 0.0 : 0.75);
  for (const Vec3& p : {Vec3(3.2, 2.8, 0.0), Vec3(2.2, 1.5, 0.0), Vec3(3.8, 1.5, 0.0),
                        Vec3(1.7, 5.2, 0.0), Vec3(2.8, 3.4, 0.75)})
    points.push_back(p);
  const nearfield::Model reference = nearfield::Model::reference(1e-3);
  size_t shadowed = 0;
  for (const auto& e : emitters)
    for (const Vec3& p : points) {
      const Vec3 up(0, 0, 1);
      const auto value = [&](const geometry::Visibility* v) {
        return nearfield::hybrid_illuminance(e, p, up, reference,
                                             nearfield::NearFieldSwitch::always, v);
      };
      const double traced = value(&rays);
      const geometry::PairVisibility pair(counting, e.vertices, std::span<const Vec3>(&p, 1));
      ASSERT_EQ(value(&pair), traced) << p.x << " " << p.y << " " << p.z;
      ASSERT_EQ(value(&tree), traced) << p.x << " " << p.y << " " << p.z;
      if (traced < value(nullptr)) ++shadowed;
    }
  // Not vacuous: shadows fall on many pairs, and the narrowed faces answer most of their nodes.
  std::printf("pairs %zu shadowed %zu, nodes from narrowed faces %zu, traced %zu\n",
              emitters.size() * points.size(), shadowed, counting.narrowed.load(),
              counting.whole.load());
  EXPECT_GT(shadowed, 15u);
  EXPECT_GT(counting.narrowed.load(), 20 * counting.whole.load());
}

}  // namespace
}  // namespace luxgrid::calc
