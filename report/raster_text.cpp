#include "report/raster_text.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <ft2build.h>
#include FT_FREETYPE_H

namespace luxgrid::report {

namespace {

// One FreeType library and its open faces per thread: an FT_Face may not be used by two threads
// at once, and opening the font for every label would cost more than drawing it. Each glyph is
// also kept once loaded (its advance, and its coverage bitmap once rendered) per pixel size, as
// are kerning pairs: a plot draws the same few dozen glyphs hundreds of times, and loading one
// runs the font's hinting program. What the cache returns is what FreeType returned.
struct Glyph {
  bool loaded = false;  // FT_Load_Glyph succeeded
  long advance_x = 0;   // 26.6 fixed point
  int left = 0, top = 0;
  unsigned rows = 0, width = 0;
  std::vector<unsigned char> coverage;  // rows x width, 0 to 255
};

class Fonts {
 public:
  Fonts() {
    if (FT_Init_FreeType(&library_) != 0) library_ = nullptr;
  }
  ~Fonts() {
    for (auto& [path, face] : faces_)
      if (face.face) FT_Done_Face(face.face);
    if (library_) FT_Done_FreeType(library_);
  }
  Fonts(const Fonts&) = delete;
  Fonts& operator=(const Fonts&) = delete;

  // The font at `file` set to `size_px`, or null when it cannot be opened or sized.
  class Sized;
  Sized* sized(const char* file, int size_px);

  class Sized {
   public:
    Sized(FT_Face face, int size_px, int* active_px)
        : face_(face), px_(size_px), active_(active_px) {}
    bool kerning() const { return FT_HAS_KERNING(face_); }
    FT_UInt index(char32_t code_point) {
      auto it = index_.find(code_point);
      if (it == index_.end())
        it = index_.emplace(code_point, FT_Get_Char_Index(face_, code_point)).first;
      return it->second;
    }
    // Kerning between two glyphs in 26.6 (0 when FreeType reports none or fails).
    long kern(FT_UInt previous, FT_UInt glyph) {
      const auto key = (static_cast<std::uint64_t>(previous) << 32) | glyph;
      auto it = kerning_.find(key);
      if (it == kerning_.end()) {
        activate();
        FT_Vector delta{};
        const long v =
            FT_Get_Kerning(face_, previous, glyph, FT_KERNING_DEFAULT, &delta) == 0 ? delta.x : 0;
        it = kerning_.emplace(key, v).first;
      }
      return it->second;
    }
    // The glyph as FT_Load_Glyph(FT_LOAD_DEFAULT) or, `rendered`, FT_LOAD_RENDER leaves it.
    const Glyph& glyph(FT_UInt index, bool rendered) {
      auto& cache = rendered ? rendered_ : outlines_;
      auto it = cache.find(index);
      if (it != cache.end()) return it->second;
      activate();
      Glyph g;
      if (FT_Load_Glyph(face_, index, rendered ? FT_LOAD_RENDER : FT_LOAD_DEFAULT) == 0) {
        const FT_GlyphSlot slot = face_->glyph;
        g.loaded = true;
        g.advance_x = slot->advance.x;
        if (rendered) {
          const FT_Bitmap& bm = slot->bitmap;
          g.left = slot->bitmap_left, g.top = slot->bitmap_top, g.rows = bm.rows,
          g.width = bm.width;
          g.coverage.resize(static_cast<std::size_t>(bm.rows) * bm.width);
          for (unsigned r = 0; r < bm.rows; ++r)
            std::copy_n(bm.buffer + static_cast<long>(r) * bm.pitch, bm.width,
                        g.coverage.begin() + static_cast<long>(r) * bm.width);
        }
      }
      return cache.emplace(index, std::move(g)).first->second;
    }

   private:
    // The face is shared by every size: set this one before FreeType computes anything.
    void activate() {
      if (*active_ != px_) FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(px_)), *active_ = px_;
    }
    FT_Face face_;
    int px_;
    int* active_;
    std::unordered_map<char32_t, FT_UInt> index_;
    std::unordered_map<std::uint64_t, long> kerning_;
    std::unordered_map<FT_UInt, Glyph> outlines_, rendered_;
  };

 private:
  struct Face {
    FT_Face face = nullptr;
    int active_px = 0;                            // the size the face is set to (0: none)
    std::map<int, std::unique_ptr<Sized>> sizes;  // null: the size cannot be set
  };
  FT_Library library_ = nullptr;
  std::map<std::string, Face> faces_;
};

Fonts::Sized* Fonts::sized(const char* file, int size_px) {
  if (!library_) return nullptr;
  auto it = faces_.find(file);
  if (it == faces_.end()) {
    Face f;
    if (FT_New_Face(library_, file, 0, &f.face) != 0) f.face = nullptr;
    it = faces_.emplace(file, std::move(f)).first;
  }
  Face& f = it->second;
  if (!f.face) return nullptr;
  auto s = f.sizes.find(size_px);
  if (s == f.sizes.end()) {
    std::unique_ptr<Sized> sized;
    if (FT_Set_Pixel_Sizes(f.face, 0, static_cast<FT_UInt>(size_px)) == 0) {
      f.active_px = size_px;
      sized = std::make_unique<Sized>(f.face, size_px, &f.active_px);
    } else {
      f.active_px = 0;
    }
    s = f.sizes.emplace(size_px, std::move(sized)).first;
  }
  return s->second.get();
}

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
  Fonts::Sized* font = fonts.sized(font_file, size_px);
  if (!font) return static_cast<int>(text.size()) * size_px * 6 / 10;
  const bool kerning = font->kerning();
  long pen_x = 0;
  FT_UInt previous = 0;
  for (std::size_t i = 0; i < text.size();) {
    const FT_UInt index = font->index(next_code_point(text, i));
    if (kerning && previous && index) pen_x += font->kern(previous, index);
    previous = index;
    const Glyph& g = font->glyph(index, false);
    if (!g.loaded) continue;
    pen_x += g.advance_x;
  }
  return static_cast<int>((pen_x + 63) >> 6);
}

bool draw_text(Raster& raster, int x, int y, std::string_view text, int size_px,
               const char* font_file, Rgb colour) {
  Fonts::Sized* font = fonts.sized(font_file, size_px);
  if (!font) return false;
  const bool kerning = font->kerning();
  long pen_x = static_cast<long>(x) * 64;  // 26.6 fixed point
  FT_UInt previous = 0;
  for (std::size_t i = 0; i < text.size();) {
    const FT_UInt index = font->index(next_code_point(text, i));
    if (kerning && previous && index) pen_x += font->kern(previous, index);
    previous = index;
    const Glyph& g = font->glyph(index, true);
    if (!g.loaded) continue;
    const int left = static_cast<int>((pen_x + 32) >> 6) + g.left, top = y - g.top;
    for (unsigned r = 0; r < g.rows; ++r) {
      const unsigned char* row = g.coverage.data() + static_cast<std::size_t>(r) * g.width;
      for (unsigned c = 0; c < g.width; ++c)
        if (row[c])
          raster.blend(left + static_cast<int>(c), top + static_cast<int>(r), colour,
                       row[c] / 255.f);
    }
    pen_x += g.advance_x;
  }
  return true;
}

}  // namespace luxgrid::report
