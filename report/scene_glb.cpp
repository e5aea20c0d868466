#include "report/scene_glb.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include <glm/gtc/quaternion.hpp>

#include "geometry/polygon3.h"
#include "report/gltf_writer.h"
#include "report/scene_meshes.h"
#include "report/viridis.h"
#include "util/format.h"

namespace luxgrid::report {

namespace {

using nlohmann::json;
using Kind = geometry::SurfaceGrid::Kind;

json xyz(const Vec3& v) { return json::array({v.x, v.y, v.z}); }

// The materials, made once each and shared.
class Materials {
 public:
  explicit Materials(gltf::Document& doc) : doc_(doc) {}
  // Grey by reflectance: a surface reflecting rho of the light is drawn with base colour rho.
  int grey(double rho) {
    const auto it = grey_.find(rho);
    if (it != grey_.end()) return it->second;
    gltf::Material m;
    m.name = "reflectance " + format_double("%.2f", rho);
    m.base_colour = {rho, rho, rho, 1.0};
    return grey_[rho] = doc_.add_material(m);
  }
  // A flat colour given in sRGB, drawn unlit.
  int flat(const std::string& name, Rgb srgb, double alpha = 1.0, bool double_sided = true) {
    const auto it = flat_.find(name);
    if (it != flat_.end()) return it->second;
    const Rgb c = srgb_to_linear(srgb);
    gltf::Material m;
    m.name = name;
    m.base_colour = {c.r, c.g, c.b, alpha};
    m.unlit = true;
    m.double_sided = double_sided;
    m.blend = alpha < 1.0;
    return flat_[name] = doc_.add_material(m);
  }

 private:
  gltf::Document& doc_;
  std::map<double, int> grey_;
  std::map<std::string, int> flat_;
};

const Rgb kOpening{1.0f, 0.85f, 0.25f};        // the plan view's yellow
const Rgb kBody{0.35f, 0.35f, 0.38f};          // a dark grey housing
const Rgb kC0Arrow{0.10f, 0.30f, 0.85f};       // the plan view's blue C0 bar
const Rgb kSolid{1.0f, 0.75f, 0.0f};           // the photometric solid, translucent
const Rgb kGridNoValues{0.20f, 0.65f, 0.30f};  // a surface before it is calculated
const Rgb kPoint{0.95f, 0.45f, 0.05f};
const Rgb kObserver{0.85f, 0.10f, 0.10f};
const Rgb kGlass{0.55f, 0.78f, 0.95f};        // a pale blue pane, translucent
const Rgb kOpeningEdge{0.05f, 0.25f, 0.60f};  // a daylight opening's outline, the plan's blue
constexpr double kSolidAlpha = 0.55;
constexpr double kGlassAlpha = 0.3;
constexpr double kMarkerRadius = 0.04;  // m

json opening_json(const photometry::LuminousOpening& o) {
  using Shape = photometry::LuminousOpening::Shape;
  return {{"shape", o.shape == Shape::rectangle ? "rectangle"
                    : o.shape == Shape::disk    ? "disk"
                                                : "point"},
          {"length_m", o.length},
          {"width_m", o.width},
          {"height_m", o.height},
          {"description", o.description}};
}

json stats_json(const calc::SurfaceResult& s) {
  return {{"Emin_lx", s.stats.Emin},
          {"Eavg_lx", s.stats.Eavg},
          {"Emax_lx", s.stats.Emax},
          {"U0", s.stats.U0},
          {"Ud", s.stats.Ud}};
}

const char* face_name(const calc::RoomFaceRef& f) {
  return f.kind == calc::RoomFaceRef::Kind::floor     ? "floor"
         : f.kind == calc::RoomFaceRef::Kind::ceiling ? "ceiling"
                                                      : "wall";
}

// A daylight opening's node: glass as a translucent pane with its outline, an unglazed opening
// as its outline alone; its glazing and place in extras.
gltf::Node daylight_opening_node(gltf::Document& doc, Materials& materials, const calc::Room& room,
                                 const calc::DaylightOpening& o) {
  gltf::Primitive edge = daylight_outline_primitive(o);
  edge.material = materials.flat("opening outline", kOpeningEdge);
  std::vector<gltf::Primitive> parts;
  if (o.glazing_transmittance) {
    gltf::Primitive pane = daylight_pane_primitive(room, o);
    pane.material = materials.flat("glazing", kGlass, kGlassAlpha);
    parts.push_back(std::move(pane));
  }
  parts.push_back(std::move(edge));
  gltf::Node node;
  node.name = o.name;
  node.mesh = doc.add_mesh(o.name, parts);
  json face = {{"kind", face_name(o.face)}};
  if (o.face.kind == calc::RoomFaceRef::Kind::wall) face["wall"] = o.face.wall;
  node.extras = {{"kind", "opening"},
                 {"room", room.name},
                 {"face", std::move(face)},
                 {"area_m2", glm::length(geometry::area_vector(o.polygon))},
                 {"frame_factor", o.frame_factor},
                 {"maintenance_factor", o.maintenance_factor}};
  if (o.glazing_transmittance)
    node.extras["glazing"] = {{"transmittance", *o.glazing_transmittance}};
  else
    node.extras["glazing"] = "none";
  return node;
}

// The rotation of a pose as glTF's unit quaternion (x, y, z, w).
std::array<double, 4> quaternion(const glm::dmat3& r) {
  const glm::dquat q = glm::normalize(glm::quat_cast(r));
  return {q.x, q.y, q.z, q.w};
}

}  // namespace

Rgb srgb_to_linear(const Rgb& c) {
  const auto f = [](float v) {
    const double s = v;
    return static_cast<float>(s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4));
  };
  return {f(c.r), f(c.g), f(c.b)};
}

ColourScale scene_colour_scale(const calc::Results& results,
                               const std::optional<ColourScale>& fixed) {
  if (fixed) return *fixed;
  bool any = false;
  double lo = 0.0, hi = 0.0;
  for (const auto& s : results.surfaces) {
    if (s.grid.kind != Kind::grid) continue;
    lo = any ? std::min(lo, s.stats.Emin) : s.stats.Emin;
    hi = any ? std::max(hi, s.stats.Emax) : s.stats.Emax;
    any = true;
  }
  return fit_scale(lo, hi);
}

double solid_length_m(const calc::Scene& scene) {
  double h = 0.0;
  for (const auto& r : scene.rooms) h = std::max(h, r.height);
  return h > 0.0 ? h / 3.0 : 1.0;
}

std::string scene_glb(const SceneGlbInput& in) {
  const calc::Scene& scene = *in.scene;
  gltf::Document doc("luxgrid " + in.version);
  Materials materials(doc);
  std::vector<int> top;  // the root's children

  // --- rooms and obstacles ------------------------------------------------------------------
  for (std::size_t r = 0; r < scene.rooms.size(); ++r) {
    const calc::Room& room = scene.rooms[r];
    std::vector<calc::DaylightOpening> openings;  // this room's
    for (const auto& o : scene.openings)
      if (o.room == r) openings.push_back(o);
    std::vector<gltf::Primitive> faces = room_primitives(room, openings);
    faces[0].material = materials.grey(room.reflectance.floor);
    faces[1].material = materials.grey(room.reflectance.walls);
    faces[2].material = materials.grey(room.reflectance.ceiling);
    gltf::Node node;
    node.name = room.name;
    node.mesh = doc.add_mesh(room.name, faces);
    node.extras = {{"kind", "room"},
                   {"floor_z_m", room.floor_z},
                   {"height_m", room.height},
                   {"reflectance",
                    {{"floor", room.reflectance.floor},
                     {"walls", room.reflectance.walls},
                     {"ceiling", room.reflectance.ceiling}}}};
    for (const auto& o : room.obstacles) {
      gltf::Primitive prism = prism_primitive(o);
      prism.material = materials.grey(o.reflectance);
      gltf::Node child;
      child.name = o.name;
      child.mesh = doc.add_mesh(o.name, {prism});
      child.extras = {{"kind", "obstacle"},
                      {"room", room.name},
                      {"z0_m", o.z0},
                      {"z1_m", o.z1},
                      {"reflectance", o.reflectance}};
      node.children.push_back(doc.add_node(std::move(child)));
    }
    for (const auto& o : openings)
      node.children.push_back(doc.add_node(daylight_opening_node(doc, materials, room, o)));
    top.push_back(doc.add_node(std::move(node)));
  }

  // --- luminaires, each with its photometric solid (one mesh per type) ------------------------
  std::map<std::string, const LuminaireType*> type_of;
  if (in.types)
    for (const auto& t : *in.types) type_of[t.key] = &t;
  double max_cd = 0.0;
  for (const auto& [key, t] : type_of)
    if (t->solid) max_cd = std::max(max_cd, t->solid->max_cd());
  const double m_per_cd = max_cd > 0.0 ? solid_length_m(scene) / max_cd : 0.0;
  std::map<std::string, int> solid_mesh;
  // One mesh per opening's shape and size, shared by the luminaires that have it.
  std::map<std::tuple<int, double, double>, int> luminaire_mesh;
  for (const calc::Luminaire& l : scene.luminaires) {
    const auto shape =
        std::make_tuple(static_cast<int>(l.opening.shape), l.opening.length, l.opening.width);
    auto mesh = luminaire_mesh.find(shape);
    if (mesh == luminaire_mesh.end()) {
      gltf::Primitive opening = opening_primitive(l.opening);
      opening.material = materials.flat("luminous opening", kOpening, 1.0, false);
      gltf::Primitive body = body_primitive(l.opening);
      body.material = materials.flat("luminaire body", kBody, 1.0, false);
      gltf::Primitive arrow = c0_arrow_primitive(l.opening);
      arrow.material = materials.flat("C0 direction", kC0Arrow);
      const std::string name = "luminaire " + opening_json(l.opening)["shape"].get<std::string>() +
                               " " + format_double("%g", l.opening.length) + " x " +
                               format_double("%g", l.opening.width) + " m";
      mesh = luminaire_mesh.emplace(shape, doc.add_mesh(name, {opening, body, arrow})).first;
    }
    gltf::Node node;
    node.name = l.label;
    node.mesh = mesh->second;
    node.translation = {l.pose.position.x, l.pose.position.y, l.pose.position.z};
    if (l.pose.rotation != glm::dmat3(1.0)) node.rotation = quaternion(l.pose.rotation);
    node.extras = {{"kind", "luminaire"},
                   {"photometry", l.photometry},
                   {"position_m", xyz(l.pose.position)},
                   {"c0_direction", xyz(l.pose.rotation * Vec3(1, 0, 0))},
                   {"aim", xyz(l.pose.rotation * Vec3(0, 0, -1))},
                   {"opening", opening_json(l.opening)}};
    const auto type = type_of.find(l.photometry);
    if (type != type_of.end() && type->second->flux_lm)
      node.extras["flux_lm"] = *type->second->flux_lm;
    if (type != type_of.end() && type->second->solid && type->second->solid->max_cd() > 0.0) {
      const PhotometricSolid& solid = *type->second->solid;
      auto mesh = solid_mesh.find(l.photometry);
      if (mesh == solid_mesh.end()) {
        gltf::Primitive p = solid_primitive(solid, m_per_cd);
        p.material = materials.flat("photometric solid", kSolid, kSolidAlpha);
        mesh = solid_mesh.emplace(l.photometry, doc.add_mesh(l.photometry + " solid", {p})).first;
      }
      gltf::Node child;
      child.name = l.label + " photometric solid";
      child.mesh = mesh->second;
      child.extras = {{"kind", "photometric_solid"},
                      {"photometry", l.photometry},
                      {"m_per_cd", m_per_cd},
                      {"max_cd", solid.max_cd()}};
      node.children.push_back(doc.add_node(std::move(child)));
    }
    top.push_back(doc.add_node(std::move(node)));
  }

  // --- surfaces -------------------------------------------------------------------------------
  const ColourScale scale = in.results ? scene_colour_scale(*in.results, in.scale)
                                       : in.scale.value_or(fit_scale(0.0, 0.0));
  std::vector<const calc::SurfaceResult*> results;
  std::vector<calc::SurfaceResult> bare;  // the scene's surfaces without values
  if (in.results) {
    for (const auto& s : in.results->surfaces) results.push_back(&s);
  } else {
    for (const auto& g : scene.surfaces) {
      calc::SurfaceResult r;
      r.grid = g;
      bare.push_back(std::move(r));
    }
    for (const auto& s : bare) results.push_back(&s);
  }
  int point_mesh = -1, observer_mesh = -1;
  for (const calc::SurfaceResult* s : results) {
    const geometry::SurfaceGrid& g = s->grid;
    const bool values = s->E.size() == g.points.size() && in.results;
    gltf::Node node;
    node.name = g.name;
    node.extras = {{"kind", geometry::to_string(g.kind)},
                   {"quantity", geometry::to_string(g.quantity)}};
    if (values) node.extras.update(stats_json(*s));
    if (s->UGR_max) node.extras["UGR_max"] = *s->UGR_max;
    std::vector<int> vertex_of;
    gltf::Primitive mesh = g.kind == Kind::grid ? grid_primitive(g, &vertex_of) : gltf::Primitive{};
    if (!mesh.indices.empty()) {
      json e = json::array(), index = json::array();
      for (std::size_t i = 0; i < g.points.size(); ++i) {
        if (vertex_of[i] < 0) continue;
        index.push_back(i);
        if (!values) continue;
        e.push_back(s->E[i]);
        const Rgb c = srgb_to_linear(viridis(scale_position(scale, s->E[i])));
        mesh.colours.insert(mesh.colours.end(), {c.r, c.g, c.b});
      }
      mesh.material = values ? materials.flat("illuminance", {1, 1, 1}, 1.0, false)
                             : materials.flat("calculation surface", kGridNoValues, 0.6, false);
      node.mesh = doc.add_mesh(g.name, {mesh});
      node.extras["point_index"] = std::move(index);
      if (values) node.extras["E_lx"] = std::move(e);
    } else {
      // Points and observers (and a grid too thin for a triangle): a marker at each active point.
      const bool observers = g.kind == Kind::observers;
      int& marker = observers ? observer_mesh : point_mesh;
      if (marker < 0) {
        gltf::Primitive p = marker_primitive(kMarkerRadius);
        p.material = materials.flat(observers ? "observer" : "point",
                                    observers ? kObserver : kPoint, 1.0, false);
        marker = doc.add_mesh(observers ? "observer marker" : "point marker", {p});
      }
      std::map<std::size_t, std::size_t> views_seen;  // observer -> views so far
      for (std::size_t i = 0; i < g.points.size(); ++i) {
        if (!g.active[i]) continue;
        gltf::Node child;
        child.name = g.name + " " + std::to_string(i + 1);
        child.mesh = marker;
        child.translation = {g.points[i].x, g.points[i].y, g.points[i].z};
        child.extras = {{"point_index", i}, {"position_m", xyz(g.points[i])}};
        if (values) child.extras["E_lx"] = s->E[i];
        if (observers && i < g.observer.size()) {
          const std::size_t o = g.observer[i], v = views_seen[o]++;
          child.extras["observer"] = o + 1;
          child.extras["view_direction"] = xyz(g.normals[i]);
          if (o < s->observers.size() && v < s->observers[o].views.size() &&
              s->observers[o].views[v].UGR)
            child.extras["UGR"] = *s->observers[o].views[v].UGR;
        }
        node.children.push_back(doc.add_node(std::move(child)));
      }
    }
    top.push_back(doc.add_node(std::move(node)));
  }

  // --- the root: luxgrid's frame in glTF's ----------------------------------------------------
  gltf::Node root;
  root.name = scene.name.empty() ? std::string("luxgrid project") : scene.name;
  root.children = std::move(top);
  root.matrix = kZUpToYUp;
  root.extras = {{"kind", "project"},
                 {"axes", "luxgrid's (x, y, z), +z up, is glTF's (x, z, -y), +y up"}};
  json colours = json::array();
  for (int k = 0; k <= 16; ++k) {
    const Rgb8 c = Raster::to_bytes(viridis(k / 16.0));
    colours.push_back(json::array({c.r, c.g, c.b}));
  }
  json extras = {{"luxgrid_version", in.version}};
  if (in.results)
    extras["colour_scale"] = {{"min_lx", scale.min},
                              {"max_lx", scale.max},
                              {"ticks_lx", scale.ticks},
                              {"srgb_at_sixteenths", std::move(colours)}};
  doc.set_scene({doc.add_node(std::move(root))}, std::move(extras));
  return doc.glb();
}

}  // namespace luxgrid::report
