// A finer reference for a large room's reflected light than a project can ask for: the project's
// rooms solved as `calc` solves them (its quality's patch size and bounces), but with the far
// ratio given here (for a clustered room the opening ratio is 1 / far ratio,
// calc/indirect/clustered.h) and the links' memory limit raised, so that the ratio is not widened.
// Writes the maintained E_indirect of every active point of every surface, one
// "surface,i,x,y,z,E_indirect_maintained_lx" line each, as the surface CSVs of `calc` give them
// (docs/indirect.md, "Large rooms": how the 200 x 100 m hall's standard compares with it).
// Run: build/bench/hall_reference PROJECT.json FAR_RATIO LINK_MB OUT.csv [PATCH_SIZE_M [BUDGET]]
// The optional patch size (m) and per-room patch budget (at most kMaxPatchesPerRoom, limits.h)
// make a room of ordinary size a finer reference than its quality meshes it at: for
// examples/lshape at `reference`, 0.15 m and 10 000 patches (docs/accuracy.md). A FAR_RATIO of 0
// keeps the quality's (at `reference`: exact factors, no point kernel).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "calc/indirect/indirect.h"
#include "calc/scene_visibility.h"
#include "project/project_file.h"

int main(int argc, char** argv) {
  using namespace luxgrid;
  if (argc < 5 || argc > 7) {
    std::fprintf(stderr,
                 "usage: hall_reference PROJECT.json FAR_RATIO LINK_MB OUT.csv [PATCH_SIZE_M "
                 "[BUDGET]]\n");
    return 2;
  }
  try {
    const project::Project p = project::load_project(argv[1]);
    const calc::Scene& scene = p.scene;
    calc::indirect::IndirectOptions options = calc::indirect::indirect_options(scene.settings);
    if (std::atof(argv[2]) > 0.0) options.far_ratio = std::atof(argv[2]);
    if (argc > 5) options.patch_size_m = std::atof(argv[5]);
    if (argc > 6) options.max_patches_per_room = static_cast<size_t>(std::atol(argv[6]));
    // What blocks light, as the plan makes it (null for a convex room without obstacles).
    calc::VisibilityDecision decision;
    options.visibility = calc::make_visibility(scene, decision);
    options.max_clustered_link_bytes =
        static_cast<size_t>(std::atof(argv[3]) * calc::indirect::kBytesPerMegabyte);
    const calc::indirect::IndirectResult r =
        calc::indirect::compute_indirect(scene, scene.surfaces, options);
    std::FILE* out = std::fopen(argv[4], "w");
    if (out == nullptr) throw std::runtime_error(std::string("cannot write ") + argv[4]);
    std::fprintf(out, "surface,i,x,y,z,E_indirect_maintained_lx\n");
    for (size_t s = 0; s < scene.surfaces.size(); ++s) {
      const auto& g = scene.surfaces[s];
      for (size_t i = 0; i < g.points.size(); ++i)
        if (g.active[i])
          std::fprintf(out, "%s,%zu,%.6f,%.6f,%.6f,%.17g\n", g.name.c_str(), i, g.points[i].x,
                       g.points[i].y, g.points[i].z,
                       r.E_indirect_per_surface[s][i] * scene.settings.maintenance_factor);
    }
    std::fclose(out);
    std::printf("%zu patches, %zu clustered links (%.0f MB), %d bounces, %.1f s\n", r.patches,
                r.clustered_links, r.clustered_bytes / 1e6, r.bounces_run, r.seconds);
    for (const auto& w : r.warnings)
      std::printf("warning: opening %.3f instead of %.3f\n", w.opening, w.quality_opening);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hall_reference: %s\n", e.what());
    return 1;
  }
  return 0;
}
