#include "report/raster_text.h"

#include <map>
#include <memory>
#include <string>

#include <ft2build.h>
#include FT_FREETYPE_H

namespace luxgrid::report {

namespace {

// One FreeType library and its open faces per thread: an FT_Face may not be used by two threads
// at once, and opening the font for every label would cost more than drawing it.
class Fonts {
 public:
  Fonts() {
    if (FT_Init_FreeType(&library_) != 0) library_ = nullptr;
  }
  ~Fonts() {
    for (auto& [path, face] : faces_)
      if (face) FT_Done_Face(face);
    if (library_) FT_Done_FreeType(library_);
  }
  Fonts(const Fonts&) = delete;
  Fonts& operator=(const Fonts&) = delete;

  FT_Face face(const char* file) {
    if (!library_) return nullptr;
    auto it = faces_.find(file);
    if (it == faces_.end()) {
      FT_Face f = nullptr;
      if (FT_New_Face(library_, file, 0, &f) != 0) f = nullptr;
      it = faces_.emplace(file, f).first;
    }
    return it->second;
  }

 private:
  FT_Library library_ = nullptr;
  std::map<std::string, FT_Face> faces_;
};

// The next code point of UTF-8 `s` from `i` (advanced past it); U+FFFD for a malformed byte.
char32_t next_code_point(std::string_view s, std::size_t& i) {
  const unsigned char c = static_cast<unsigned char>(s[i++]);
  if (c < 0x80) return c;
  const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : -1;
  if (extra < 0) return 0xFFFD;
  char32_t cp = c & (0x3F >> extra);
  for (int k = 0; k < extra; ++k) {
    if (i >= s.size() || (static_cast<unsigned char>(s[i]) & 0xC0) != 0x80) return 0xFFFD;
    cp = (cp << 6) | (static_cast<unsigned char>(s[i++]) & 0x3F);
  }
  return cp;
}

}  // namespace

namespace {
thread_local Fonts fonts;
}  // namespace

int text_width(std::string_view text, int size_px, const char* font_file) {
  FT_Face face = fonts.face(font_file);
  if (!face || FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px)) != 0)
    return static_cast<int>(text.size()) * size_px * 6 / 10;
  long pen_x = 0;
  FT_UInt previous = 0;
  for (std::size_t i = 0; i < text.size();) {
    const FT_UInt glyph = FT_Get_Char_Index(face, next_code_point(text, i));
    if (FT_HAS_KERNING(face) && previous && glyph) {
      FT_Vector delta;
      if (FT_Get_Kerning(face, previous, glyph, FT_KERNING_DEFAULT, &delta) == 0) pen_x += delta.x;
    }
    previous = glyph;
    if (FT_Load_Glyph(face, glyph, FT_LOAD_DEFAULT) != 0) continue;
    pen_x += face->glyph->advance.x;
  }
  return static_cast<int>((pen_x + 63) >> 6);
}

bool draw_text(Raster& raster, int x, int y, std::string_view text, int size_px,
               const char* font_file, Rgb colour) {
  FT_Face face = fonts.face(font_file);
  if (!face || FT_Set_Pixel_Sizes(face, 0, static_cast<FT_UInt>(size_px)) != 0) return false;
  const bool kerning = FT_HAS_KERNING(face);
  long pen_x = static_cast<long>(x) * 64;  // 26.6 fixed point
  FT_UInt previous = 0;
  for (std::size_t i = 0; i < text.size();) {
    const FT_UInt glyph = FT_Get_Char_Index(face, next_code_point(text, i));
    if (kerning && previous && glyph) {
      FT_Vector delta;
      if (FT_Get_Kerning(face, previous, glyph, FT_KERNING_DEFAULT, &delta) == 0) pen_x += delta.x;
    }
    previous = glyph;
    if (FT_Load_Glyph(face, glyph, FT_LOAD_RENDER) != 0) continue;
    const FT_GlyphSlot g = face->glyph;
    const FT_Bitmap& bm = g->bitmap;
    const int left = static_cast<int>((pen_x + 32) >> 6) + g->bitmap_left, top = y - g->bitmap_top;
    for (unsigned r = 0; r < bm.rows; ++r) {
      const unsigned char* row = bm.buffer + static_cast<long>(r) * bm.pitch;
      for (unsigned c = 0; c < bm.width; ++c)
        if (row[c])
          raster.blend(left + static_cast<int>(c), top + static_cast<int>(r), colour,
                       row[c] / 255.f);
    }
    pen_x += g->advance.x;
  }
  return true;
}

}  // namespace luxgrid::report
