#pragma once
// The daylight tests' flux balances (what lands on the surfaces = what they absorb + what their
// reflected light sends out through the openings): the interreflection solved with a given first
// bounce, and the flux its surfaces absorb.
#include <cstddef>
#include <memory>
#include <utility>

#include "calc/indirect/indirect.h"

namespace luxgrid::calc {

// The scene's interreflection at `standard` with `incident` (PatchMesh -> lm per patch) as its
// first bounce.
template <class Incident>
std::unique_ptr<const indirect::IndirectSolution> solve_with_first_bounce(const Scene& scene,
                                                                          Incident incident) {
  indirect::IndirectOptions o;
  o.quality = Quality::standard;
  o.incident_flux_lm = std::move(incident);
  return indirect::solve_indirect(scene, o);
}

// (1 - rho) / rho x each patch's exitant flux, summed (lm).
inline double absorbed_flux_lm(const indirect::IndirectSolution& solution) {
  double absorbed = 0.0;
  for (std::size_t i = 0; i < solution.mesh.patches.size(); ++i) {
    const double rho = solution.mesh.patches[i].reflectance;
    absorbed += (1.0 - rho) / rho * solution.exitant_flux_lm[i];
  }
  return absorbed;
}

}  // namespace luxgrid::calc
