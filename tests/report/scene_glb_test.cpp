// scene.glb (report/scene_glb.h) and its writer (report/gltf_writer.h), read back byte by byte:
// the GLB container, accessors' bounds against the data, names, the +z-up to +y-up turn of a
// known point, the luminaires' rotations, and the surfaces' colours against the colour scale.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "report/gltf_writer.h"
#include "report/html_report.h"
#include "report/photometric_solid.h"
#include "report/room_figures.h"
#include "report/scene_glb.h"
#include "report/scene_meshes.h"
#include "report/viridis.h"

namespace luxgrid::report {
namespace {

using nlohmann::json;

std::uint32_t u32(const std::string& b, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, b.data() + at, 4);
  return v;
}

// A .glb taken apart as the specification lays it out [glTF2] 4.4, with each check it states.
struct Glb {
  json doc;
  std::string bin;
  explicit Glb(const std::string& b) {
    EXPECT_EQ(u32(b, 0), 0x46546C67u);  // "glTF"
    EXPECT_EQ(u32(b, 4), 2u);
    EXPECT_EQ(u32(b, 8), b.size());
    const std::uint32_t json_length = u32(b, 12);
    EXPECT_EQ(json_length % 4, 0u);
    EXPECT_EQ(u32(b, 16), 0x4E4F534Au);  // "JSON"
    doc = json::parse(b.substr(20, json_length));
    const std::size_t at = 20 + json_length;
    if (at < b.size()) {
      const std::uint32_t bin_length = u32(b, at);
      EXPECT_EQ(u32(b, at + 4), 0x004E4942u);  // "BIN\0"
      EXPECT_EQ(bin_length % 4, 0u);
      EXPECT_EQ(at + 8 + bin_length, b.size());
      bin = b.substr(at + 8, bin_length);
      EXPECT_EQ(doc["buffers"][0]["byteLength"].get<std::size_t>(), bin.size());
    }
  }
  template <class T>
  std::vector<T> data(int accessor) const {
    const json& a = doc["accessors"][accessor];
    const json& v = doc["bufferViews"][a["bufferView"].get<int>()];
    const std::size_t n = a["count"].get<std::size_t>() * (a["type"] == "VEC3" ? 3 : 1);
    EXPECT_EQ(v["byteLength"].get<std::size_t>(), n * sizeof(T));
    EXPECT_EQ(v["byteOffset"].get<std::size_t>() % 4, 0u);
    EXPECT_LE(v["byteOffset"].get<std::size_t>() + n * sizeof(T), bin.size());
    std::vector<T> out(n);
    std::memcpy(out.data(), bin.data() + v["byteOffset"].get<std::size_t>(), n * sizeof(T));
    return out;
  }
  const json* node(const std::string& name) const {
    for (const json& n : doc["nodes"])
      if (n["name"] == name) return &n;
    return nullptr;
  }
};

TEST(GltfWriter, BoundsAndBufferLengthsMatchTheData) {
  gltf::Document doc("test");
  gltf::Primitive p;
  p.positions = {0.5f, -1.0f, 2.0f, 3.0f, 4.0f, -5.25f, -0.125f, 0.0f, 1.0f};
  p.indices = {0, 1, 2};
  gltf::Primitive q = p;
  q.positions.resize(6);  // two vertices: a second accessor at an offset
  q.indices = {0, 1, 1};
  const int mesh = doc.add_mesh("m", {p, q});
  gltf::Node n;
  n.name = "a node";
  n.mesh = mesh;
  doc.set_scene({doc.add_node(n)}, nullptr);
  const Glb glb(doc.glb());
  const json& prims = glb.doc["meshes"][0]["primitives"];
  ASSERT_EQ(prims.size(), 2u);
  const json& a = glb.doc["accessors"][prims[0]["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(a["min"], json::array({-0.125, -1.0, -5.25}));
  EXPECT_EQ(a["max"], json::array({3.0, 4.0, 2.0}));
  EXPECT_EQ(glb.data<float>(prims[0]["attributes"]["POSITION"]), p.positions);
  EXPECT_EQ(glb.data<float>(prims[1]["attributes"]["POSITION"]), q.positions);
  EXPECT_EQ(glb.data<std::uint32_t>(prims[1]["indices"]), q.indices);
  const json& b = glb.doc["accessors"][prims[1]["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(b["max"], json::array({3.0, 4.0, 2.0}));
  EXPECT_EQ(b["count"], 2);
  EXPECT_EQ(glb.doc["nodes"][0]["name"], "a node");
  EXPECT_EQ(glb.doc["asset"]["version"], "2.0");
}

TEST(GltfWriter, RefusesAnIndexOutOfRangeAndColoursOfTheWrongLength) {
  gltf::Document doc("test");
  gltf::Primitive p;
  p.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  p.indices = {0, 1, 3};
  EXPECT_THROW(doc.add_mesh("m", {p}), std::invalid_argument);
  p.indices = {0, 1, 2};
  p.colours = {1, 1, 1};
  EXPECT_THROW(doc.add_mesh("m", {p}), std::invalid_argument);
  // Without triangles: no mesh.
  EXPECT_EQ(doc.add_mesh("m", {gltf::Primitive{}}), -1);
}

TEST(SceneGlb, SrgbToLinearFollowsIec61966) {
  EXPECT_EQ(srgb_to_linear({0, 0, 0}).r, 0.0f);
  EXPECT_NEAR(srgb_to_linear({1, 1, 1}).g, 1.0f, 1e-6);
  // 0.5 -> ((0.5 + 0.055) / 1.055)^2.4 = 0.214041; 0.04 lies on the linear part: 0.04 / 12.92.
  EXPECT_NEAR(srgb_to_linear({0.5f, 0, 0}).r, 0.214041f, 1e-6);
  EXPECT_NEAR(srgb_to_linear({0, 0, 0.04f}).b, 0.04f / 12.92f, 1e-7);
}

// Lambertian downwards: I = 1000 cos(gamma) cd below the horizon, nothing above.
struct Downlight : photometry::IntensityDistribution {
  double intensity(const Vec3& d) const override { return d.z < 0.0 ? -1000.0 * d.z : 0.0; }
};

// A 4 x 3 m room, 2.7 m high; a luminaire at (1, 2, 2.5) aimed along +x (rotated -90 degrees
// about y); a 3 x 2 workplane at 0.8 m with E = 100 + 10 x lx; two points.
struct TestScene {
  calc::Scene scene;
  calc::Results results;
  std::vector<LuminaireType> types;
  TestScene() {
    scene.name = "test project";
    calc::Room room;
    room.name = "the room";
    room.outline = {{0, 0}, {4, 0}, {4, 3}, {0, 3}};
    room.height = 2.7;
    room.reflectance = {0.2, 0.5, 0.7};
    room.obstacles.push_back(geometry::make_box("desk", {1, 1, 0}, {2, 1.8, 0.75}, 0.0, 0.4));
    scene.rooms.push_back(room);
    calc::Luminaire l;
    l.label = "luminaire 1";
    l.photometry = "down";
    l.pose.position = {1, 2, 2.5};
    l.pose.rotation = calc::rotation_xyz(0, -kPi / 2, 0);
    l.opening.shape = photometry::LuminousOpening::Shape::rectangle;
    l.opening.length = 0.6;
    l.opening.width = 0.3;
    scene.luminaires.push_back(l);
    LuminaireType t;
    t.key = "down";
    t.solid = photometric_solid(Downlight{});
    types.push_back(t);
    calc::SurfaceResult s;
    s.grid = geometry::make_plane_grid("workplane", {0.5, 0.5, 0.8}, {1, 0, 0}, {0, 1, 0}, 3.0, 2.0,
                                       1.0);
    s.grid.active[1] = false;  // a point inside an obstacle
    for (const Vec3& p : s.grid.points) s.E.push_back(100.0 + 10.0 * p.x);
    s.E_direct = s.E;
    s.E_indirect.assign(s.E.size(), 0.0);
    s.stats = {120.0, 130.0, 140.0, 0.9, 0.8};
    results.surfaces.push_back(s);
    calc::SurfaceResult pts;
    pts.grid.name = "probes";
    pts.grid.kind = geometry::SurfaceGrid::Kind::points;
    pts.grid.points = {{1, 1, 0.8}, {2, 2, 0.8}};
    pts.grid.normals = {{0, 0, 1}, {0, 0, 1}};
    pts.grid.active = {true, true};
    pts.grid.nu = 2;
    pts.grid.nv = 1;
    pts.E = {50.0, 60.0};
    results.surfaces.push_back(pts);
  }
  std::string glb(std::optional<ColourScale> scale = std::nullopt) const {
    SceneGlbInput in;
    in.scene = &scene;
    in.results = &results;
    in.types = &types;
    in.scale = scale;
    in.version = "test";
    return scene_glb(in);
  }
};

// glTF's column-major 4 x 4 matrix applied to a point.
Vec3 transform_point(const json& m, const Vec3& p) {
  const auto e = [&](int row, int col) { return m[col * 4 + row].get<double>(); };
  return {e(0, 0) * p.x + e(0, 1) * p.y + e(0, 2) * p.z + e(0, 3),
          e(1, 0) * p.x + e(1, 1) * p.y + e(1, 2) * p.z + e(1, 3),
          e(2, 0) * p.x + e(2, 1) * p.y + e(2, 2) * p.z + e(2, 3)};
}

TEST(SceneGlb, NamesTheProjectsObjectsAndTurnsZUpIntoYUp) {
  const TestScene t;
  const Glb glb(t.glb());
  for (const char* name : {"test project", "the room", "desk", "luminaire 1",
                           "luminaire 1 photometric solid", "workplane", "probes", "probes 2"})
    EXPECT_NE(glb.node(name), nullptr) << name;
  const json& root = *glb.node("test project");
  EXPECT_EQ(glb.doc["scenes"][0]["nodes"].size(), 1u);
  // The luminaire at luxgrid (1, 2, 2.5), +z up, is at glTF (1, 2.5, -2), +y up.
  const json& l = *glb.node("luminaire 1");
  const Vec3 p(l["translation"][0], l["translation"][1], l["translation"][2]);
  EXPECT_EQ(p, Vec3(1, 2, 2.5));
  EXPECT_EQ(transform_point(root["matrix"], p), Vec3(1, 2.5, -2));
  EXPECT_EQ(transform_point(root["matrix"], Vec3(0, 0, 1)), Vec3(0, 1, 0));  // up is up
  EXPECT_EQ(l["extras"]["photometry"], "down");
  // The room's materials are grey by reflectance: floor, walls, ceiling.
  const json& room_mesh = glb.doc["meshes"][glb.node("the room")->at("mesh").get<int>()];
  for (int k = 0; k < 3; ++k) {
    const double rho = std::array<double, 3>{0.2, 0.5, 0.7}[k];
    const json& m = glb.doc["materials"][room_mesh["primitives"][k]["material"].get<int>()];
    EXPECT_EQ(m["pbrMetallicRoughness"]["baseColorFactor"], json::array({rho, rho, rho, 1.0}));
  }
  // The floor's vertices lie at z = 0 and span the outline.
  const json& floor =
      glb.doc["accessors"][room_mesh["primitives"][0]["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(floor["min"], json::array({0.0, 0.0, 0.0}));
  EXPECT_EQ(floor["max"], json::array({4.0, 3.0, 0.0}));
  EXPECT_EQ(glb.node("probes 2")->at("extras")["E_lx"], 60.0);
}

TEST(SceneGlb, TheSolidPointsWhereTheLuminaireIsAimed) {
  const TestScene t;
  const Glb glb(t.glb());
  const json& l = *glb.node("luminaire 1");
  const glm::dquat q(l["rotation"][3].get<double>(), l["rotation"][0].get<double>(),
                     l["rotation"][1].get<double>(), l["rotation"][2].get<double>());
  EXPECT_NEAR(glm::length(q), 1.0, 1e-12);
  // The solid's farthest vertex, in the luminaire's frame, is straight down (its peak, 1000 cd
  // at nadir) at a third of the room's height; turned by the node's rotation it points along +x.
  const json& solid = *glb.node("luminaire 1 photometric solid");
  const json& mesh = glb.doc["meshes"][solid["mesh"].get<int>()];
  const auto v = glb.data<float>(mesh["primitives"][0]["attributes"]["POSITION"]);
  Vec3 far(0.0);
  for (std::size_t i = 0; i < v.size(); i += 3)
    if (glm::length(Vec3(v[i], v[i + 1], v[i + 2])) > glm::length(far))
      far = Vec3(v[i], v[i + 1], v[i + 2]);
  EXPECT_NEAR(far.z, -2.7 / 3.0, 1e-6);
  EXPECT_NEAR(std::hypot(far.x, far.y), 0.0, 1e-6);
  const Vec3 world = q * far;
  EXPECT_NEAR(world.x, 0.9, 1e-6);
  EXPECT_NEAR(world.y, 0.0, 1e-6);
  EXPECT_NEAR(world.z, 0.0, 1e-6);
  EXPECT_NEAR(solid["extras"]["m_per_cd"].get<double>(), 0.9 / 1000.0, 1e-12);
}

TEST(SceneGlb, SurfaceColoursAreTheColourScalesAtEachPointsValue) {
  const TestScene t;
  for (const std::optional<ColourScale>& fixed :
       {std::optional<ColourScale>{}, std::optional<ColourScale>(fixed_scale(0, 200))}) {
    const Glb glb(t.glb(fixed));
    const json& node = *glb.node("workplane");
    const json& prim = glb.doc["meshes"][node["mesh"].get<int>()]["primitives"][0];
    const auto colours = glb.data<float>(prim["attributes"]["COLOR_0"]);
    const auto positions = glb.data<float>(prim["attributes"]["POSITION"]);
    const json& E = node["extras"]["E_lx"];
    const json& index = node["extras"]["point_index"];
    const auto& s = t.results.surfaces[0];
    // One vertex per active point, in order: 5 of the 3 x 2 grid's 6.
    ASSERT_EQ(E.size(), 5u);
    ASSERT_EQ(colours.size(), 15u);
    const ColourScale scale = scene_colour_scale(t.results, fixed);
    EXPECT_EQ(scale.min, fixed ? 0.0 : fit_scale(120.0, 140.0).min);
    for (std::size_t k = 0; k < E.size(); ++k) {
      const std::size_t i = index[k];
      EXPECT_TRUE(s.grid.active[i]);
      EXPECT_EQ(E[k].get<double>(), s.E[i]);
      const Rgb want = srgb_to_linear(viridis(scale_position(scale, s.E[i])));
      EXPECT_EQ(colours[3 * k], want.r);
      EXPECT_EQ(colours[3 * k + 1], want.g);
      EXPECT_EQ(colours[3 * k + 2], want.b);
      // Lifted kGridLift along the normal (+z), else where the point is.
      EXPECT_FLOAT_EQ(positions[3 * k], static_cast<float>(s.grid.points[i].x));
      EXPECT_FLOAT_EQ(positions[3 * k + 2], static_cast<float>(0.8 + kGridLift));
    }
    const json& cs = glb.doc["scenes"][0]["extras"]["colour_scale"];
    EXPECT_EQ(cs["min_lx"].get<double>(), scale.min);
    EXPECT_EQ(cs["max_lx"].get<double>(), scale.max);
    const Rgb8 top = Raster::to_bytes(viridis(1.0));
    EXPECT_EQ(cs["srgb_at_sixteenths"][16], json::array({top.r, top.g, top.b}));
  }
}

TEST(SceneGlb, ALargeGridIsDrawnWithEveryKthLineAndItsEdges) {
  // 250 x 10 points: every third column (0, 3, ..., 249: 84 of them; 249 is the last) and every
  // row, so the drawing spans the grid's whole extent.
  geometry::SurfaceGrid g =
      geometry::make_plane_grid("big", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 25.0, 1.0, 0.1);
  ASSERT_EQ(g.nu, 250);
  ASSERT_EQ(g.nv, 10);
  std::vector<int> vertex_of;
  const gltf::Primitive p = grid_primitive(g, &vertex_of);
  EXPECT_EQ(p.positions.size(), 3u * 84 * 10);
  EXPECT_EQ(p.indices.size(), 3u * 2 * 83 * 9);
  EXPECT_GE(vertex_of[249], 0);
  EXPECT_GE(vertex_of[3], 0);
  EXPECT_EQ(vertex_of[1], -1);
  float xmin = 1e9f, xmax = -1e9f;
  for (std::size_t i = 0; i < p.positions.size(); i += 3) {
    xmin = std::min(xmin, p.positions[i]);
    xmax = std::max(xmax, p.positions[i]);
  }
  EXPECT_FLOAT_EQ(xmin, static_cast<float>(g.points.front().x));
  EXPECT_FLOAT_EQ(xmax, static_cast<float>(g.points[249].x));
}

TEST(SceneGlb, TheSameInputWritesTheSameBytes) {
  const TestScene t;
  EXPECT_EQ(t.glb(), t.glb());
}

TEST(SceneView, AReportWithoutThreeJsSaysTheViewIsNotAvailable) {
  const TestScene t;
  const std::string glb = t.glb();
  ReportInput in;
  in.results = &t.results;
  in.scene = &t.scene;
  in.rooms = room_figures(t.scene);
  in.scene_glb = &glb;
  in.three_js = {};
  const std::string page = html_report(in);
  EXPECT_NE(page.find("id=\"scene-3d\""), std::string::npos);
  EXPECT_NE(page.find("The 3D view is not available"), std::string::npos);
  EXPECT_EQ(page.find("<script"), std::string::npos);
  in.three_js = "/* three */";
  const std::string with = html_report(in);
  EXPECT_EQ(with.find("The 3D view is not available"), std::string::npos);
  EXPECT_NE(with.find("<script type=\"text/plain\" id=\"scene-3d-three\">/* three */</script>"),
            std::string::npos);
  EXPECT_NE(with.find("id=\"scene-3d-glb\">" + base64(glb) + "</script>"), std::string::npos);
}

}  // namespace
}  // namespace luxgrid::report
