#include "report/surface_npy.h"

#include "report/npy.h"

namespace luxgrid::report {

std::string surface_npy(const calc::SurfaceResult& r) {
  const auto& g = r.grid;
  const std::size_t n = g.points.size();
  std::string out = npy_float64_header({n, static_cast<std::size_t>(kSurfaceNpyColumns)});
  out.reserve(out.size() + n * kSurfaceNpyColumns * 8);
  auto at = [](const std::vector<double>& v, std::size_t k) { return k < v.size() ? v[k] : 0.0; };
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = g.points[k];
    for (double v : {p.x, p.y, p.z, at(r.E, k), at(r.E_direct, k), at(r.E_indirect, k)})
      append_float64_le(out, v);
  }
  return out;
}

}  // namespace luxgrid::report
