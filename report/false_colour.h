#pragma once
// False-colour PNG of a grid surface, drawn to scale with axes in metres: viridis (perceptual,
// monotonic in lightness so it survives grey print), interpolated bilinearly between the grid
// points, the room outline and obstacles, the surface's own outline, isolux lines at the legend's
// round values and at each stated requirement, labels that do not overlap, luminaire openings,
// and a legend in lux. The HTML report embeds these same PNGs.
//
// Orientation (report/map_frame.h): horizontal surfaces are drawn as the plan, +x right and +y up
// (a ceiling as a reflected ceiling plan: seen from below as in a mirror on the floor, so it
// lines up with the plan); vertical surfaces seen from the side their normal faces (a room's wall
// from inside the room), up at the top; tilted surfaces along their own u (right) and v (up).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "calc/results.h"
#include "calc/scene.h"
#include "report/colour_scale.h"

namespace luxgrid::report {

struct PlotOverlay {
  bool isolux = true;  // contour lines at the scale's ticks and at required_lx
  const calc::Scene* scene =
      nullptr;                      // rooms (outline, obstacles) and luminaires; null: none drawn
  std::vector<double> required_lx;  // stated requirement values (Em, Emin): a labelled line each
  // What the map shows when it is not illuminance (the daylight factor: "DF", "%"), for the
  // statistics line and the legend; the values are the result's E either way.
  std::string quantity = "E", unit = "lx";
  // Contour lines at exactly these values (labelled with the unit) instead of the scale's round
  // values: the daylight factor's 1, 2 and 5 %. Empty: the round values.
  std::vector<double> levels;
};

// The contour lines a map of values from `min` to `max` gets: each requirement inside the range
// (`required`), then the overlay's fixed levels, or else the scale's round values (isolux_levels),
// each value once.
struct PlotLevel {
  double value;
  bool required;
};
std::vector<PlotLevel> plot_levels(const PlotOverlay& overlay, const ColourScale& scale, double min,
                                   double max);

// Where the map lies in the picture: its top-left pixel, its size in pixels and its scale.
struct MapPixels {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  double px_per_m = 0.0;
};

// What each pixel of a grid's map shows (outside the room, off the surface, an obstacle, or
// which grid points it is interpolated from with which weights): the same for every plot of one
// grid and scene (the total and its direct and reflected parts), so it can be worked out once
// for all of them. Made by map_samples, used by write_false_colour_png.
struct MapSamples;
std::shared_ptr<const MapSamples> map_samples(const calc::SurfaceResult& r,
                                              const calc::Scene* scene);

// Writes `path` (PNG). Returns "" on success or a warning (e.g. no font for labels: the image
// is written without text, and the caller reports the warning). `where`, when given, receives
// the map's place in the picture (its origin is map_frame(r.grid, overlay.scene).origin).
// `samples`: map_samples(of a result on this grid, overlay.scene), else they are made here (as
// they are when they were made for another grid size, other active points or another scene).
// `png`, when given, receives the file's bytes (for report.html); with an empty `path` they are
// made without writing a file.
std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path, const PlotOverlay& overlay,
                                   MapPixels* where = nullptr, const MapSamples* samples = nullptr,
                                   std::string* png = nullptr);
std::string write_false_colour_png(const calc::SurfaceResult& r, const ColourScale& scale,
                                   const std::filesystem::path& path);

}  // namespace luxgrid::report
