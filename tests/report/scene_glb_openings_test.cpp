// Daylight openings in scene.glb (report/scene_glb.h): the room faces they lie in drawn with them
// cut out, read back from the .glb's own bytes (float positions: areas to 1e-5 relative), and
// each opening a node of its room with its glazing in extras: glass as a translucent pane and
// its outline, an unglazed opening as its outline alone. The project is tests/data's daylit
// office: two 2 x 1.5 m windows in wall 0 (y = 0) and a 1 x 1 m roof light.
#include <gtest/gtest.h>

#include <cstring>

#include <nlohmann/json.hpp>

#include "geometry/polygon.h"
#include "project/project_file.h"
#include "report/scene_glb.h"

namespace luxgrid::report {
namespace {

using nlohmann::json;

struct OpeningsGlb {
  json doc;
  std::string bin;
  explicit OpeningsGlb(const std::string& b) {
    std::uint32_t json_length = 0;
    std::memcpy(&json_length, b.data() + 12, 4);
    doc = json::parse(b.substr(20, json_length));
    bin = b.substr(20 + json_length + 8);
  }
  template <class T>
  std::vector<T> data(int accessor) const {
    const json& a = doc["accessors"][accessor];
    const json& v = doc["bufferViews"][a["bufferView"].get<int>()];
    const std::size_t n = a["count"].get<std::size_t>() * (a["type"] == "VEC3" ? 3 : 1);
    std::vector<T> out(n);
    std::memcpy(out.data(), bin.data() + v["byteOffset"].get<std::size_t>(), n * sizeof(T));
    return out;
  }
  const json& node(const std::string& name) const {
    for (const json& n : doc["nodes"])
      if (n["name"] == name) return n;
    throw std::runtime_error("no node " + name);
  }
  // The triangles of a primitive, as corner triples.
  std::vector<std::array<Vec3, 3>> triangles(const json& primitive) const {
    const auto p = data<float>(primitive["attributes"]["POSITION"].get<int>());
    const auto idx = data<std::uint32_t>(primitive["indices"].get<int>());
    std::vector<std::array<Vec3, 3>> out;
    for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
      std::array<Vec3, 3> tri;
      for (int k = 0; k < 3; ++k)
        tri[k] = Vec3(p[3 * idx[t + k]], p[3 * idx[t + k] + 1], p[3 * idx[t + k] + 2]);
      out.push_back(tri);
    }
    return out;
  }
};

const json& primitives_of(const OpeningsGlb& glb, const std::string& node) {
  return glb.doc["meshes"][glb.node(node)["mesh"].get<int>()]["primitives"];
}

OpeningsGlb daylit_office_glb() {
  static const calc::Scene scene =
      project::load_project(LUXGRID_SOURCE_DIR "/tests/data/daylight_office/project.json").scene;
  SceneGlbInput in;
  in.scene = &scene;
  in.version = "test";
  return OpeningsGlb(scene_glb(in));
}

TEST(SceneGlbOpenings, WallsAndCeilingLoseTheOpeningsAreas) {
  const OpeningsGlb glb = daylit_office_glb();
  const json& faces = primitives_of(glb, "office");
  ASSERT_EQ(faces.size(), 3u);
  const auto area = [](const std::vector<std::array<Vec3, 3>>& ts) {
    double a = 0.0;
    for (const auto& t : ts) a += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
    return a;
  };
  // Floor 6 x 4 m whole; walls 2 (6 + 4) x 2.8 less two windows of 2 x 1.5; ceiling less 1 x 1.
  EXPECT_NEAR(area(glb.triangles(faces[0])), 24.0, 24.0 * 1e-5);
  EXPECT_NEAR(area(glb.triangles(faces[1])), 56.0 - 6.0, 56.0 * 1e-5);
  EXPECT_NEAR(area(glb.triangles(faces[2])), 23.0, 24.0 * 1e-5);
}

TEST(SceneGlbOpenings, NoFaceTriangleCoversAnOpeningAndEachFacesTheRoom) {
  const OpeningsGlb glb = daylit_office_glb();
  const json& faces = primitives_of(glb, "office");
  const Vec3 centre(3.0, 2.0, 1.4);
  for (int f = 0; f < 3; ++f)
    for (const auto& t : glb.triangles(faces[f])) {
      const Vec3 c = (t[0] + t[1] + t[2]) / 3.0;
      const Vec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
      // Facing into the room: towards the room's centre from the face's plane.
      EXPECT_GT(glm::dot(n, centre - c), 0.0) << "face " << f << " at " << c.x << " " << c.y;
      // Not in the windows (wall y = 0: x and z) nor the roof light (ceiling: x and y).
      const geometry::Polygon2 window_left = {{0.5, 0.9}, {2.5, 0.9}, {2.5, 2.4}, {0.5, 2.4}};
      const geometry::Polygon2 window_right = {{3.5, 0.9}, {5.5, 0.9}, {5.5, 2.4}, {3.5, 2.4}};
      const geometry::Polygon2 roof = {{2.5, 2.5}, {3.5, 2.5}, {3.5, 3.5}, {2.5, 3.5}};
      if (f == 1 && std::abs(c.y) < 1e-6) {
        EXPECT_EQ(geometry::locate({c.x, c.z}, window_left, 0.0), geometry::Location::outside);
        EXPECT_EQ(geometry::locate({c.x, c.z}, window_right, 0.0), geometry::Location::outside);
      }
      if (f == 2) {
        EXPECT_EQ(geometry::locate({c.x, c.y}, roof, 0.0), geometry::Location::outside);
      }
    }
}

TEST(SceneGlbOpenings, GlassIsATranslucentPaneAndAnUnglazedOpeningItsOutline) {
  const OpeningsGlb glb = daylit_office_glb();
  // Children of their room.
  const json& office = glb.node("office");
  std::vector<std::string> children;
  for (int c : office["children"]) children.push_back(glb.doc["nodes"][c]["name"]);
  for (const char* name : {"window left", "window right", "roof light"})
    EXPECT_NE(std::find(children.begin(), children.end(), name), children.end()) << name;

  const json& window = glb.node("window left");
  EXPECT_EQ(window["extras"]["kind"], "opening");
  EXPECT_EQ(window["extras"]["room"], "office");
  EXPECT_EQ(window["extras"]["glazing"]["transmittance"], 0.8);
  EXPECT_EQ(window["extras"]["frame_factor"], 0.8);
  EXPECT_EQ(window["extras"]["maintenance_factor"], 0.9);
  EXPECT_EQ(window["extras"]["face"], json({{"kind", "wall"}, {"wall", 0}}));
  EXPECT_NEAR(window["extras"]["area_m2"].get<double>(), 3.0, 1e-12);
  const json& pane = primitives_of(glb, "window left");
  ASSERT_EQ(pane.size(), 2u);
  EXPECT_FALSE(pane[0].contains("mode"));  // triangles
  const json& glass = glb.doc["materials"][pane[0]["material"].get<int>()];
  EXPECT_EQ(glass["alphaMode"], "BLEND");
  EXPECT_LT(glass["pbrMetallicRoughness"]["baseColorFactor"][3].get<double>(), 1.0);
  double pane_area = 0.0;
  for (const auto& t : glb.triangles(pane[0]))
    pane_area += 0.5 * glm::length(glm::cross(t[1] - t[0], t[2] - t[0]));
  EXPECT_NEAR(pane_area, 3.0, 3.0 * 1e-6);
  EXPECT_EQ(pane[1]["mode"], 2);  // LINE_LOOP through the four corners
  EXPECT_EQ(glb.data<std::uint32_t>(pane[1]["indices"].get<int>()).size(), 4u);

  const json& roof = glb.node("roof light");
  EXPECT_EQ(roof["extras"]["glazing"], "none");
  EXPECT_EQ(roof["extras"]["face"]["kind"], "ceiling");
  const json& outline = primitives_of(glb, "roof light");
  ASSERT_EQ(outline.size(), 1u);
  EXPECT_EQ(outline[0]["mode"], 2);
}

}  // namespace
}  // namespace luxgrid::report
