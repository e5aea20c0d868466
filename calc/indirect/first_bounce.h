#pragma once
// The first bounce, RSM-style ([Dachsbacher2005], [Gadia2024]): the luminous flux
// each luminaire sends onto each patch, found by integrating the luminaire's intensity over the
// patch's solid angle. A patch with flux Phi = reflectance x incident lumens is one virtual point
// light (VPL). Where an RSM rasterises the room into a (cube) shadow map from the luminaire, this
// integrates over the same directions deterministically: each patch is a fan of triangles from
// its centroid, each triangle subdivided 4^level times, each piece weighted by its exact solid
// angle (Van Oosterom-Strackee) times I in the direction of its centroid, with visibility tested
// per piece. Because the patches of a closed room tile the sphere around the luminaire, the exact
// solid angles sum to 4 pi, so the received flux equals the emitted flux up to the quadrature
// error of I alone (zero for an isotropic source).
//
// A luminaire is not one point: its luminous opening, clipped to the room, is cut into cells
// (emitter_cells.h), each a point source carrying its area fraction of the intensity; ordinary
// openings, small against the room, stay one point at their centre.
#include <map>
#include <string>
#include <vector>

#include "calc/indirect/form_factor.h"
#include "calc/indirect/indirect_notes.h"
#include "calc/indirect/patches.h"
#include "calc/scene.h"
#include "geometry/visibility.h"

namespace luxgrid::calc::indirect {

struct FirstBounce {
  std::vector<double> incident_flux_lm;  // per patch: direct lumens received
  std::vector<double> vpl_flux_lm;       // per patch: reflectance x incident
  // Flux entering the rooms: each luminaire's luminous_flux times the fraction of its opening
  // inside a room (emitter_cells.h); light from the part outside never enters.
  double emitted_flux_lm = 0.0;
  double luminaire_flux_lm = 0.0;   // sum of luminous_flux over luminaires reaching a room
  double received_flux_lm = 0.0;    // sum of incident_flux_lm
  size_t vpl_count = 0;             // patches with vpl flux > 0
  std::vector<IndirectNote> notes;  // e.g. luminaires outside every room
};

// `visibility[r]` is room r's visibility test (null: nothing blocks; geometry/visibility.h).
// `max_angle_rad` is the largest angular size of one integration piece (0.08 rad by default:
// I is sampled at least every ~4.6 degrees).
// `known_flux_lm`: luminous_flux of distributions already integrated (others are computed).
// `intensity_lookup`: what each luminaire's distribution is looked up in for the pieces'
// intensities (calc/intensity_lookup.h: a texture, no atan2); missing or null: the distribution
// itself. The luminous flux is always the distribution's own.
// `one_piece_rooms` (per room; rooms with the clustered transfer, clustered.h): a patch whose
// pieces would span at most 2 max_angle_rad, where nothing blocks, is one piece: its exact solid
// angle (one atan2) times I towards its centroid, instead of a fan of triangles each with its own
// solid angle and intensity: a quarter of the work on the ~10^5 far patches of a hall, with an
// error of second order in the patch's angular size (the midpoint rule of I alone).
FirstBounce first_bounce(
    const Scene& scene, const PatchMesh& mesh,
    const std::vector<const geometry::Visibility*>& visibility, double max_angle_rad = 0.08,
    const std::map<const photometry::IntensityDistribution*, double>* known_flux_lm = nullptr,
    const std::map<const photometry::IntensityDistribution*, photometry::DistributionPtr>*
        intensity_lookup = nullptr,
    const std::vector<char>* one_piece_rooms = nullptr);

// From fb.incident_flux_lm (one per patch of `mesh`): each patch's VPL flux (reflectance x
// incident), the received total and the VPL count. first_bounce ends with it; light entering
// through openings (IndirectOptions::incident_flux_lm) goes through it too.
void add_reflected_flux(const PatchMesh& mesh, FirstBounce& fb);

}  // namespace luxgrid::calc::indirect
