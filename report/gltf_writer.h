#pragma once
// A small glTF 2.0 writer [glTF2]: meshes of triangles (positions, optionally per-vertex colours),
// materials, a node tree with names and extras, one scene, written as one binary .glb (a JSON chunk
// and a BIN chunk holding one buffer). Only what scene.glb needs (report/scene_glb.h); every
// accessor gets its own buffer view, every positions accessor its min and max as the format
// requires. Deterministic: the same calls give the same bytes.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace luxgrid::report::gltf {

struct Material {
  std::string name;
  std::array<double, 4> base_colour{1, 1, 1, 1};  // linear RGBA (glTF's baseColorFactor)
  std::array<double, 3> emissive{0, 0, 0};        // linear RGB
  bool unlit = false;         // KHR_materials_unlit: shown in its colours, whatever the lighting
  bool double_sided = false;  // else only the side the triangles' winding faces is drawn
  bool blend = false;         // alphaMode BLEND (translucent by base_colour's alpha)
};

// [glTF2] 3.7.2.1: what a primitive's indices draw.
enum class Mode { lines = 1, line_loop = 2, triangles = 4 };

// One list of triangles: three indices into the mesh's vertices each, counter-clockwise seen from
// the side the triangle faces. Or lines: two indices each, or one closed line through them all.
struct Primitive {
  std::vector<float> positions;  // x, y, z per vertex
  std::vector<float> colours;    // r, g, b per vertex (linear, in [0, 1]); empty: none
  std::vector<std::uint32_t> indices;
  int material = -1;  // index from add_material; -1: glTF's default material
  Mode mode = Mode::triangles;
};

struct Node {
  std::string name;
  int mesh = -1;  // -1: none
  std::vector<int> children;
  // Local to parent: a 4 x 4 matrix in glTF's column-major order, or translation, rotation
  // (unit quaternion x, y, z, w) and scale. Left out when not set.
  std::optional<std::array<double, 16>> matrix;
  std::optional<std::array<double, 3>> translation;
  std::optional<std::array<double, 4>> rotation;
  std::optional<std::array<double, 3>> scale;
  nlohmann::json extras;  // null: none
};

class Document {
 public:
  explicit Document(std::string generator);

  int add_material(const Material& m);
  // Primitives without triangles are left out; a mesh left with none is not added (returns -1,
  // a node without mesh). Throws std::invalid_argument for an index out of range, colours that
  // do not match the positions or a count of indices that does not fit the mode (a multiple of
  // three triangles, of two for lines, at least two for a loop).
  int add_mesh(const std::string& name, const std::vector<Primitive>& primitives);
  int add_node(Node node);
  Node& node(int index) { return nodes_.at(static_cast<std::size_t>(index)); }
  // The scene's root nodes, and its extras.
  void set_scene(std::vector<int> roots, nlohmann::json extras);

  // The .glb file: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros).
  std::string glb() const;
  // The JSON chunk's document, as glb() writes it.
  nlohmann::json document() const;

 private:
  // A buffer view over `bytes` appended to the buffer (at a multiple of 4), and an accessor over
  // it; returns the accessor's index.
  int add_accessor(const void* bytes, std::size_t size, int target, int component_type,
                   std::size_t count, const char* type, nlohmann::json min, nlohmann::json max);
  std::string generator_;
  std::string bin_;
  nlohmann::json buffer_views_ = nlohmann::json::array();
  nlohmann::json accessors_ = nlohmann::json::array();
  nlohmann::json materials_ = nlohmann::json::array();
  nlohmann::json meshes_ = nlohmann::json::array();
  std::vector<Node> nodes_;
  std::vector<int> roots_;
  nlohmann::json scene_extras_;
  bool unlit_used_ = false;
};

}  // namespace luxgrid::report::gltf
