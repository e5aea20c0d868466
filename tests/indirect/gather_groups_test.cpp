// The final gather's groups (calc/indirect/gather.h make_gather_set) hold one plane each. A
// receiver skips a whole group unless it lies in front of it; with one bounce only the lit faces
// emit, and the floor and a cabinet's top (both facing up, with only dark faces between them in
// the mesh's order) were one group: every point below the top's plane lost the floor's light.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "calc/indirect/gather.h"
#include "calc/indirect/patches.h"
#include "calc/scene_visibility.h"
#include "tests/indirect/l_room.h"

namespace luxgrid::calc::indirect {
namespace {

TEST(GatherGroups, AParallelFaceBehindTheReceiverDoesNotHideTheFloor) {
  const Scene scene = l_scene("groups");
  const PatchMesh mesh = build_patch_mesh(scene, 0.4);
  VisibilityDecision decision;
  const std::shared_ptr<const geometry::Visibility> visibility = make_visibility(scene, decision);
  // Exitance on the floor and on the cabinet's top (1.6 m) alone, varied so a missing term shows;
  // every face between them in the mesh's order dark.
  std::vector<double> floor_and_top(mesh.patches.size(), 0.0), floor_only = floor_and_top;
  size_t top_patches = 0;
  for (size_t j = 0; j < mesh.patches.size(); ++j) {
    const Patch& p = mesh.patches[j];
    const double flux = 1.0 + static_cast<double>(j % 7) * 0.37;
    if (p.face == FaceKind::floor) floor_and_top[j] = floor_only[j] = flux;
    if (p.face == FaceKind::obstacle && p.normal.z > 0.5) {
      floor_and_top[j] = flux;
      ++top_patches;
    }
  }
  ASSERT_GT(top_patches, 0u);
  const GatherSet with_top = make_gather_set(mesh, 0, mesh.patches.size(), floor_and_top, 5.0);
  const GatherSet without = make_gather_set(mesh, 0, mesh.patches.size(), floor_only, 5.0);
  // Points below the top's plane, looking down at the floor: the top faces away from them, so
  // its light adds exactly nothing and the floor's is all they get (the same terms in the same
  // order: equal to the bit). Some beside the cabinet, some across the room.
  size_t points = 0;
  for (const Vec3& p : {Vec3(1.2, 1.9, 0.8), Vec3(2.1, 1.4, 1.2), Vec3(0.5, 0.5, 0.8),
                        Vec3(5.0, 1.0, 1.5), Vec3(1.0, 3.5, 1.0)}) {
    const Vec3 down(0.0, 0.0, -1.0);
    const double a = gather_set_point(mesh, with_top, p, down, 5.0, visibility.get());
    const double b = gather_set_point(mesh, without, p, down, 5.0, visibility.get());
    EXPECT_GT(b, 0.0) << "at " << p.x << ", " << p.y << ", " << p.z;
    EXPECT_EQ(a, b) << "at " << p.x << ", " << p.y << ", " << p.z;
    ++points;
  }
  EXPECT_EQ(points, 5u);
  // And above the top, looking down, a point gets both: more than the floor's alone.
  const Vec3 above(2.1, 1.9, 2.0), down(0.0, 0.0, -1.0);
  EXPECT_GT(gather_set_point(mesh, with_top, above, down, 5.0, visibility.get()),
            gather_set_point(mesh, without, above, down, 5.0, visibility.get()));
}

}  // namespace
}  // namespace luxgrid::calc::indirect
