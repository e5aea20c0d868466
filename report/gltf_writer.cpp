#include "report/gltf_writer.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace luxgrid::report::gltf {

namespace {

using nlohmann::json;

// [glTF2] 3.6.2: buffer view targets, accessor component types.
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
// [glTF2] 4.4: the GLB header's magic ("glTF"), version, and the chunk types "JSON" and "BIN\0".
constexpr std::uint32_t kMagic = 0x46546C67;
constexpr std::uint32_t kVersion = 2;
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;

// The buffer holds floats and integers as this machine stores them, which glTF requires to be
// little endian.
static_assert(std::endian::native == std::endian::little, "glTF buffers are little endian");

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);  // little endian
}

// Per component, the least and the greatest of `values` taken `n` at a time.
std::pair<json, json> bounds(const std::vector<float>& values, int n) {
  std::vector<float> lo(n, std::numeric_limits<float>::infinity());
  std::vector<float> hi(n, -std::numeric_limits<float>::infinity());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const int c = static_cast<int>(i % static_cast<std::size_t>(n));
    lo[c] = std::min(lo[c], values[i]);
    hi[c] = std::max(hi[c], values[i]);
  }
  // As doubles: a float converts exactly, and the JSON number reads back as the same float.
  json min = json::array(), max = json::array();
  for (int c = 0; c < n; ++c) {
    min.push_back(static_cast<double>(lo[c]));
    max.push_back(static_cast<double>(hi[c]));
  }
  return {min, max};
}

json colour(const double* c, int n) { return json(std::vector<double>(c, c + n)); }

}  // namespace

Document::Document(std::string generator) : generator_(std::move(generator)) {}

int Document::add_accessor(const void* bytes, std::size_t size, int target, int component_type,
                           std::size_t count, const char* type, json min, json max) {
  while (bin_.size() % 4 != 0) bin_ += '\0';  // every component type here is 4 bytes
  const std::size_t offset = bin_.size();
  bin_.append(static_cast<const char*>(bytes), size);
  buffer_views_.push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
  json a = {{"bufferView", buffer_views_.size() - 1},
            {"componentType", component_type},
            {"count", count},
            {"type", type}};
  if (!min.is_null()) a["min"] = std::move(min);
  if (!max.is_null()) a["max"] = std::move(max);
  accessors_.push_back(std::move(a));
  return static_cast<int>(accessors_.size() - 1);
}

int Document::add_material(const Material& m) {
  json pbr = {{"baseColorFactor", colour(m.base_colour.data(), 4)},
              {"metallicFactor", 0.0},
              {"roughnessFactor", 1.0}};
  json j = {{"name", m.name}, {"pbrMetallicRoughness", std::move(pbr)}};
  if (m.emissive != std::array<double, 3>{0, 0, 0})
    j["emissiveFactor"] = colour(m.emissive.data(), 3);
  if (m.double_sided) j["doubleSided"] = true;
  if (m.blend) j["alphaMode"] = "BLEND";
  if (m.unlit) {
    j["extensions"] = {{"KHR_materials_unlit", json::object()}};
    unlit_used_ = true;
  }
  materials_.push_back(std::move(j));
  return static_cast<int>(materials_.size() - 1);
}

int Document::add_mesh(const std::string& name, const std::vector<Primitive>& primitives) {
  json prims = json::array();
  for (const Primitive& p : primitives) {
    // Nothing to draw (a degenerate outline, an opening of no size): left out.
    if (p.indices.empty()) continue;
    const std::size_t vertices = p.positions.size() / 3;
    const std::size_t per = p.mode == Mode::triangles ? 3 : p.mode == Mode::lines ? 2 : 1;
    const bool fits =
        p.indices.size() % per == 0 && (p.mode != Mode::line_loop || p.indices.size() >= 2);
    if (vertices == 0 || p.positions.size() % 3 != 0 || !fits ||
        (!p.colours.empty() && p.colours.size() != p.positions.size()))
      throw std::invalid_argument("glTF mesh \"" + name + "\": malformed primitive");
    for (std::uint32_t i : p.indices)
      if (i >= vertices)
        throw std::invalid_argument("glTF mesh \"" + name + "\": index out of range");
    auto [pmin, pmax] = bounds(p.positions, 3);
    json attributes = {
        {"POSITION", add_accessor(p.positions.data(), p.positions.size() * 4, kArrayBuffer, kFloat,
                                  vertices, "VEC3", std::move(pmin), std::move(pmax))}};
    if (!p.colours.empty())
      attributes["COLOR_0"] = add_accessor(p.colours.data(), p.colours.size() * 4, kArrayBuffer,
                                           kFloat, vertices, "VEC3", nullptr, nullptr);
    json prim = {
        {"attributes", std::move(attributes)},
        {"indices", add_accessor(p.indices.data(), p.indices.size() * 4, kElementArrayBuffer,
                                 kUnsignedInt, p.indices.size(), "SCALAR", nullptr, nullptr)}};
    if (p.material >= 0) prim["material"] = p.material;
    if (p.mode != Mode::triangles) prim["mode"] = static_cast<int>(p.mode);  // else the default
    prims.push_back(std::move(prim));
  }
  if (prims.empty()) return -1;
  meshes_.push_back({{"name", name}, {"primitives", std::move(prims)}});
  return static_cast<int>(meshes_.size() - 1);
}

int Document::add_node(Node node) {
  nodes_.push_back(std::move(node));
  return static_cast<int>(nodes_.size() - 1);
}

void Document::set_scene(std::vector<int> roots, json extras) {
  roots_ = std::move(roots);
  scene_extras_ = std::move(extras);
}

nlohmann::json Document::document() const {
  nlohmann::json j;
  j["asset"] = {{"version", "2.0"}, {"generator", generator_}};
  if (unlit_used_) j["extensionsUsed"] = {"KHR_materials_unlit"};
  nlohmann::json scene = {{"nodes", roots_}};
  if (!scene_extras_.is_null()) scene["extras"] = scene_extras_;
  j["scene"] = 0;
  j["scenes"] = nlohmann::json::array({std::move(scene)});
  nlohmann::json nodes = nlohmann::json::array();
  for (const Node& n : nodes_) {
    nlohmann::json o = {{"name", n.name}};
    if (n.mesh >= 0) o["mesh"] = n.mesh;
    if (!n.children.empty()) o["children"] = n.children;
    if (n.matrix) o["matrix"] = *n.matrix;
    if (n.translation) o["translation"] = *n.translation;
    if (n.rotation) o["rotation"] = *n.rotation;
    if (n.scale) o["scale"] = *n.scale;
    if (!n.extras.is_null()) o["extras"] = n.extras;
    nodes.push_back(std::move(o));
  }
  j["nodes"] = std::move(nodes);
  if (!materials_.empty()) j["materials"] = materials_;
  if (!meshes_.empty()) {
    j["meshes"] = meshes_;
    j["accessors"] = accessors_;
    j["bufferViews"] = buffer_views_;
    j["buffers"] = nlohmann::json::array({{{"byteLength", (bin_.size() + 3) / 4 * 4}}});
  }
  return j;
}

std::string Document::glb() const {
  std::string text = document().dump();
  while (text.size() % 4 != 0) text += ' ';  // [glTF2] 4.4.3.1: JSON padded with spaces
  std::string bin = bin_;
  while (bin.size() % 4 != 0) bin += '\0';  // the BIN chunk padded with zeros
  const bool has_bin = !bin.empty();
  const std::size_t total = 12 + 8 + text.size() + (has_bin ? 8 + bin.size() : 0);
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("scene.glb would exceed the 4 GiB a .glb can hold");
  std::string out;
  out.reserve(total);
  put_u32(out, kMagic);
  put_u32(out, kVersion);
  put_u32(out, static_cast<std::uint32_t>(total));
  put_u32(out, static_cast<std::uint32_t>(text.size()));
  put_u32(out, kChunkJson);
  out += text;
  if (has_bin) {
    put_u32(out, static_cast<std::uint32_t>(bin.size()));
    put_u32(out, kChunkBin);
    out += bin;
  }
  return out;
}

}  // namespace luxgrid::report::gltf
