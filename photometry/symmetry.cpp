#include "photometry/symmetry.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "photometry/limits.h"
#include "util/error.h"

namespace luxgrid::photometry {

namespace {

bool same(double a, double b) { return std::abs(a - b) < kSameAngleDeg; }

std::size_t index_of(const std::vector<double>& angles, double a) {
  for (std::size_t k = 0; k < angles.size(); ++k)
    if (same(angles[k], a)) return k;
  throw CalculationError("symmetry expansion: no stored plane at C = " + std::to_string(a));
}

std::vector<double> to_rad(const std::vector<double>& deg) {
  std::vector<double> r(deg.size());
  for (std::size_t k = 0; k < deg.size(); ++k) r[k] = deg[k] * kDegToRad;
  return r;
}
}  // namespace

bool type_c_symmetry(const std::vector<double>& h, Symmetry& out) {
  if (h.empty()) return false;
  const double first = h.front(), last = h.back();
  if (h.size() == 1) {
    out = Symmetry::rotational;
    return true;
  }
  if (same(first, 0.0) && same(last, 90.0))
    out = Symmetry::quadrant;
  else if (same(first, 0.0) && same(last, 180.0))
    out = Symmetry::bilateral_c0_c180;
  else if (same(first, 90.0) && same(last, 270.0))
    out = Symmetry::bilateral_c90_c270;
  else if (same(first, 0.0) && last > 180.0 && last <= 360.0 + kSameAngleDeg)
    out = Symmetry::none;
  else
    return false;
  return true;
}

SphericalGrid expand_type_c(const StoredPlanes& p, Symmetry symmetry,
                            std::vector<std::string>* notes) {
  const std::size_t ng = p.v_deg.size();
  SphericalGrid g;
  g.gamma_rad = to_rad(p.v_deg);
  auto plane = [&](std::size_t i) { return p.cd.begin() + static_cast<std::ptrdiff_t>(i * ng); };

  if (symmetry == Symmetry::rotational) {
    g.c_rad = {0.0};
    g.cd.assign(plane(0), plane(0) + static_cast<std::ptrdiff_t>(ng));
    return g;
  }
  // Full-circle C angle -> the stored angle whose data it shows.
  std::map<double, double> full;  // key rounded by insertion check below
  auto add = [&](double c, double stored) {
    c = std::fmod(c, 360.0);
    if (c < 0) c += 360.0;
    if (same(c, 360.0)) c = 0.0;
    for (auto& [k, v] : full)
      if (same(k, c)) return;  // the mirror planes (0, 90, 180, ...) coincide
    full.emplace(c, stored);
  };
  for (double c : p.h_deg) {
    switch (symmetry) {
      case Symmetry::quadrant:
        add(c, c), add(180.0 - c, c), add(180.0 + c, c), add(360.0 - c, c);
        break;
      case Symmetry::bilateral_c0_c180: add(c, c), add(360.0 - c, c); break;
      case Symmetry::bilateral_c90_c270: add(c, c), add(180.0 - c, c); break;
      default:
        if (!same(c, 360.0)) add(c, c);
        break;
    }
  }
  for (auto& [c, stored] : full) {
    g.c_rad.push_back(c * kDegToRad);
    auto src = plane(index_of(p.h_deg, stored));
    g.cd.insert(g.cd.end(), src, src + static_cast<std::ptrdiff_t>(ng));
  }
  // A closing 360 plane is the 0 plane again; where a file disagrees with itself, use the mean.
  if (symmetry == Symmetry::none && same(p.h_deg.back(), 360.0) && same(p.h_deg.front(), 0.0)) {
    auto last = plane(p.h_deg.size() - 1);
    bool differs = false;
    for (std::size_t j = 0; j < ng; ++j) {
      double& a = g.cd[j];
      const double b = last[static_cast<std::ptrdiff_t>(j)];
      if (std::abs(a - b) > 1e-9 * std::max(1.0, std::abs(a))) differs = true;
      a = 0.5 * (a + b);
    }
    if (differs && notes) notes->push_back("the C360 plane differs from C0; their mean is used");
  }
  return g;
}

SphericalGrid expand_type_ab(const StoredPlanes& p, PhotometricType type,
                             glm::dmat3& table_from_luminaire) {
  // The luminaire's axes in luxgrid's frame (symmetry.h; derivation in docs/photometry.md).
  const Vec3 aim(0.0, 0.0, -1.0), up(1.0, 0.0, 0.0), lateral(0.0, -1.0, 0.0);
  // Grid frame (x', y', z'): pole -z' is the hinge axis, C' = 0 is the photometric axis.
  //   type B: x' = d.A, y' = d.U, z' = -d.L  (pole at L, C' = V, gamma' = 90 - H)
  //   type A: x' = d.A, y' = d.L, z' = -d.U  (pole at U, C' = H, gamma' = 90 - V)
  const bool type_b = type == PhotometricType::B;
  const Vec3 row_y = type_b ? up : lateral;
  const Vec3 row_z = -(type_b ? lateral : up);
  // glm matrices are column-major: m[col][row].
  glm::dmat3 m(0.0);
  for (int k = 0; k < 3; ++k) {
    m[k][0] = aim[k];
    m[k][1] = row_y[k];
    m[k][2] = row_z[k];
  }
  table_from_luminaire = m;

  // Mirror H = 0..90 to -90..90 (lateral symmetry), as LM-63 allows for types A and B.
  std::vector<double> h = p.h_deg;
  const std::size_t nv = p.v_deg.size();
  std::vector<double> cd = p.cd;  // h-major
  if (same(h.front(), 0.0) && h.size() > 1) {
    std::vector<double> hm;
    std::vector<double> cdm;
    for (std::size_t k = h.size(); k-- > 1;) {
      hm.push_back(-h[k]);
      cdm.insert(cdm.end(), cd.begin() + static_cast<std::ptrdiff_t>(k * nv),
                 cd.begin() + static_cast<std::ptrdiff_t>((k + 1) * nv));
    }
    hm.insert(hm.end(), h.begin(), h.end());
    cdm.insert(cdm.end(), cd.begin(), cd.end());
    h = std::move(hm);
    cd = std::move(cdm);
  }
  auto value = [&](std::size_t ih, std::size_t iv) { return cd[ih * nv + iv]; };

  // The pole-bearing angle becomes gamma' = 90 - angle, the other becomes C'.
  const bool b = type_b;
  const std::vector<double>& lat = b ? h : p.v_deg;  // latitude-like: -> gamma'
  const std::vector<double>& lon = b ? p.v_deg : h;  // longitude-like: -> C'
  SphericalGrid g;
  for (std::size_t k = lat.size(); k-- > 0;) g.gamma_rad.push_back((90.0 - lat[k]) * kDegToRad);
  const std::size_t ngp = g.gamma_rad.size();
  auto sample = [&](std::size_t ilon, std::size_t ilat) {
    return b ? value(ilat, ilon) : value(ilon, ilat);
  };
  // C' = longitude mod 360, sorted; planes beyond the data get zero, a hair outside the last
  // measured plane (the file says nothing behind the luminaire).
  struct Plane {
    double c;
    std::vector<double> v;
  };
  std::vector<Plane> planes;
  for (std::size_t ilon = 0; ilon < lon.size(); ++ilon) {
    double c = std::fmod(lon[ilon], 360.0);
    if (c < 0) c += 360.0;
    if (same(c, 360.0)) c = 0.0;
    Plane pl{c, std::vector<double>(ngp)};
    for (std::size_t k = 0; k < ngp; ++k) pl.v[k] = sample(ilon, lat.size() - 1 - k);
    bool dup = false;
    for (auto& q : planes) dup = dup || same(q.c, c);
    if (!dup) planes.push_back(std::move(pl));
  }
  const double span = lon.back() - lon.front();
  if (span < 360.0 - kSameAngleDeg && lon.size() > 1) {
    // A zero plane 1e-4 deg outside each end: an (almost) step to zero where the data stop.
    constexpr double kEdgeDeg = 1e-4;
    std::vector<Plane> extra;
    for (double c : {lon.back() + kEdgeDeg, lon.front() - kEdgeDeg}) {
      c = std::fmod(c + 360.0, 360.0);
      bool dup = false;
      for (auto& q : planes) dup = dup || same(q.c, c);
      if (dup) continue;
      Plane zero{c, std::vector<double>(ngp, 0.0)};
      extra.push_back(std::move(zero));
    }
    for (auto& e : extra) planes.push_back(std::move(e));
    // The edge of the data is a line where the intensity steps to zero, and it runs through the
    // poles (H = +-90 for type B): there is no continuity to restore there, and averaging the
    // poles with the zero planes would darken measured directions. Keep the measured values.
    g.average_poles = false;
  }
  std::sort(planes.begin(), planes.end(),
            [](const Plane& a, const Plane& b2) { return a.c < b2.c; });
  for (auto& pl : planes) {
    g.c_rad.push_back(pl.c * kDegToRad);
    g.cd.insert(g.cd.end(), pl.v.begin(), pl.v.end());
  }
  return g;
}

}  // namespace luxgrid::photometry
