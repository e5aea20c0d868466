#pragma once
// Isolux lines by marching squares (Lorensen & Cline's 2-D case): the grid's points are the
// corners of squares; each square whose corners straddle the level contributes one segment (two
// for a saddle), its ends placed on the edges by linear interpolation.
#include <vector>

#include "report/colour_scale.h"

namespace luxgrid::report {

// In grid index coordinates: point (i, j) of the grid sits at x = i, y = j.
struct IsoSegment {
  double x0, y0, x1, y1;
};

// Segments of the contour E = level over an nu x nv row-major grid (u first). Squares with a
// corner that is not active (inside an obstacle) are skipped. Saddles are resolved by the mean
// of the four corners.
std::vector<IsoSegment> isolux_segments(const std::vector<double>& E, int nu, int nv, double level,
                                        const std::vector<bool>& active = {});

// The same for several levels in one pass over the squares: element k holds
// isolux_segments(E, nu, nv, levels[k], active).
std::vector<std::vector<IsoSegment>> isolux_segments(const std::vector<double>& E, int nu, int nv,
                                                     const std::vector<double>& levels,
                                                     const std::vector<bool>& active = {});

// Round contour levels: the scale's ticks strictly inside (min, max) and inside the data range.
std::vector<double> isolux_levels(const ColourScale& scale, double emin, double emax);

}  // namespace luxgrid::report
