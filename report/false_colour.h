#pragma once
// False-colour PNG of a grid surface: viridis (perceptual, monotonic in lightness so it survives
// grey print), a legend in lux, the surface name and its statistics, isolux lines at the legend's
// round values with labels, and luminaire positions. The HTML report embeds these same PNGs.
#include <filesystem>
#include <string>
#include <vector>

#include "calc/results.h"
#include "report/colour_scale.h"

namespace luxgrid::report {

struct PlotOverlay {
  bool isolux = true;            // contour lines at the scale's ticks, labelled in lux
  std::vector<Vec3> luminaires;  // world positions; marked where they project into a
                                 // horizontal grid's rectangle (walls get no marks)
};

// Writes `path` (PNG). Returns "" on success or a warning (e.g. no font for labels: the image
// is written without text, and the caller reports the warning).
std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path, const PlotOverlay& overlay);
std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path);

// Where a world point falls on the plot of grid `g`, as fractions of its width (left to right,
// along u) and height (top to bottom, v up). False when `g` is not roughly horizontal (normal
// within 45 degrees of vertical) or the point lies outside its rectangle.
bool plot_position(const geometry::SurfaceGrid& g, const Vec3& world, double& fx, double& fy);

}  // namespace luxgrid::report
