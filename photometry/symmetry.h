#pragma once
// Symmetry expansion: from the planes a file stores to the full-sphere grid TabularDistribution
// looks up. Readers decide which symmetry a file declares (and report errors with file and line);
// this file only mirrors planes.
//
// Type C (IES horizontal angles / EULUMDAT C planes, in degrees):
//   rotational         one plane, any C
//   quadrant           0..90: C, 180-C, 180+C, 360-C
//   bilateral C0-C180  0..180: C, 360-C
//   bilateral C90-C270 90..270: C, 180-C (mod 360)
//   none               0..<=360: a closing 360 plane is merged with 0 (mean, so the seam is
//                      continuous); an open range (0..345) wraps back to 0.
//
// Types A and B are mapped into luxgrid's frame turned so that the photometric axis (H = V = 0)
// points to nadir. The luminaire's own axes, the same for both types (derivation with sources in
// docs/photometry.md, "Types A and B"):
//   A = -z  aim, photometric zero (H = 0, V = 0)
//   U = +x  H = 0, V = +90: LM-63's "photometric horizontal", along which the luminous opening's
//           length is measured, so it lies where type C puts length (C0, +x)
//   L = -y  H = +90: horizontal angles increase clockwise seen from U (LM-63-2002), so
//           L = A x U; it is the type B polar axis (the floodlight's tilt axis, its width)
//   type B (H, V): d = cos H (cos V A + sin V U) + sin H L   (V planes hinge on L)
//   type A (H, V): d = cos V (cos H A + sin H L) + sin V U   (H planes hinge on U)
// In luxgrid's coordinates type B is sin H = -d.y, tan V = d.x / -d.z. Each is stored as a
// C-style grid whose pole is L (type B) or U (type A); where the file has no data (behind the
// luminaire) the intensity is zero.
#include <string>
#include <vector>

#include <glm/mat3x3.hpp>

#include "photometry/photometry.h"
#include "photometry/tabular_distribution.h"

namespace luxgrid::photometry {

struct StoredPlanes {
  std::vector<double> h_deg;  // C (type C) or horizontal angle H (A, B), ascending
  std::vector<double> v_deg;  // gamma (type C) or vertical angle V (A, B), ascending
  std::vector<double> cd;     // h-major: cd[i * v_deg.size() + j], absolute candela
};

// Expands type-C planes stored with `symmetry` to the full C range. `notes` receives remarks
// (e.g. "C360 plane differs from C0: their mean is used").
SphericalGrid expand_type_c(const StoredPlanes& planes, Symmetry symmetry,
                            std::vector<std::string>* notes = nullptr);

// Type A/B: builds the grid in the rotated frame; horizontal angles 0..90 are mirrored to
// -90..0 (lateral symmetry). Returns the matrix taking luminaire directions into the grid frame.
SphericalGrid expand_type_ab(const StoredPlanes& planes, PhotometricType type,
                             glm::dmat3& table_from_luminaire);

// Which symmetry a list of type-C angles (degrees, ascending) implies; false if none fits.
bool type_c_symmetry(const std::vector<double>& h_deg, Symmetry& out);

}  // namespace luxgrid::photometry
