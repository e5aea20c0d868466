#pragma once
// Text on a Raster, rendered with FreeType from a TrueType font file (anti-aliased, kerned).
// Fonts are opened once per thread and kept, so pictures can be drawn on several threads.
#include <string_view>

#include "report/raster.h"

namespace luxgrid::report {

// The font every plot uses (Debian package fonts-dejavu-core).
inline constexpr const char* kPlotFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// Draws UTF-8 `text` with its left edge at x and its baseline at y, `size_px` pixels per em.
// Returns false (drawing nothing) when the font file cannot be opened.
bool draw_text(Raster& raster, int x, int y, std::string_view text, int size_px,
               const char* font_file, Rgb colour);

// The advance width of `text` in pixels as draw_text sets it; an estimate of 0.6 em per character
// when the font cannot be opened (so label layout does not depend on the font being there).
int text_width(std::string_view text, int size_px, const char* font_file);

}  // namespace luxgrid::report
