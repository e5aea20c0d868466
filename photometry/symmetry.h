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
// Types A and B are mapped into luxgrid's frame with the photometric axis (H = V = 0) at nadir
// (-z), the lateral axis (H > 0) along +x and the B/A "up" direction (V > 0) along +y: a
// floodlight aimed horizontally along +y with +z up, turned 90 deg about x to point down.
//   type B (H, V): d = cos H (cos V A + sin V U) + sin H L   (B planes hinge on L)
//   type A (H, V): d = cos V (cos H A + sin H L) + sin V U   (A planes hinge on U)
// with A = -z, L = +x, U = +y. Each is stored as a C-style grid whose pole is L (type B) or U
// (type A); where the file has no data (behind the luminaire) the intensity is zero.
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
