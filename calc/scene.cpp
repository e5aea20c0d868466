#include "calc/scene.h"

#include <cmath>

namespace luxgrid::calc {

const char* to_string(Quality q) {
  switch (q) {
    case Quality::draft: return "draft";
    case Quality::standard: return "standard";
    case Quality::high: return "high";
    case Quality::reference: return "reference";
  }
  return "?";
}

const char* to_string(LightingScene s) {
  switch (s) {
    case LightingScene::emergency: return "emergency";
    case LightingScene::daylight: return "daylight";
    case LightingScene::normal: break;
  }
  return "normal";
}

std::optional<Quality> quality_from_string(const std::string& s) {
  if (s == "draft") return Quality::draft;
  if (s == "standard") return Quality::standard;
  if (s == "high") return Quality::high;
  if (s == "reference") return Quality::reference;
  return std::nullopt;
}

glm::dmat3 rotation_xyz(double rx, double ry, double rz) {
  // glm matrices are column-major: m[col][row]. Each is a right-handed rotation about a world
  // axis; applying x first, then y, then z gives Rz * Ry * Rx.
  const double cx = std::cos(rx), sx = std::sin(rx);
  const double cy = std::cos(ry), sy = std::sin(ry);
  const double cz = std::cos(rz), sz = std::sin(rz);
  const glm::dmat3 mx(1, 0, 0, 0, cx, sx, 0, -sx, cx);
  const glm::dmat3 my(cy, 0, -sy, 0, 1, 0, sy, 0, cy);
  const glm::dmat3 mz(cz, sz, 0, -sz, cz, 0, 0, 0, 1);
  return mz * my * mx;
}

}  // namespace luxgrid::calc
