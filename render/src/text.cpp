#include "softtune/render/text.h"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

#include "softtune/render/font.h"

namespace softtune::render {
namespace {

// Debian's fonts-dejavu-core puts it here when fontconfig does not answer.
constexpr const char* kFallbackFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

bool readable(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f) std::fclose(f);
  return f != nullptr;
}

// The font file, found once per process: fontconfig's best match for "DejaVu Sans"; empty if none.
const std::string& font_path() {
  static const std::string path = [] {
    std::string found;
    if (FcConfig* config = FcInitLoadConfigAndFonts()) {
      FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("DejaVu Sans"));
      FcConfigSubstitute(config, pattern, FcMatchPattern);
      FcDefaultSubstitute(pattern);
      FcResult result = FcResultNoMatch;
      if (FcPattern* match = FcFontMatch(config, pattern, &result)) {
        FcChar8* file = nullptr;
        if (FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch && file) found = reinterpret_cast<char*>(file);
        FcPatternDestroy(match);
      }
      FcPatternDestroy(pattern);
      FcConfigDestroy(config);
    }
    if (found.empty() || !readable(found)) found = readable(kFallbackFontPath) ? kFallbackFontPath : "";
    return found;
  }();
  return path;
}

struct Glyph {
  int width = 0, rows = 0, left = 0, top = 0, advance = 0;  // px; top: rows above the baseline
  std::vector<std::uint8_t> coverage;
};

// One FreeType library and face per thread (FreeType objects are not shared between threads), with the
// glyphs it has rendered, by code point and size.
class Face {
 public:
  Face() {
    if (font_path().empty() || FT_Init_FreeType(&library_) != 0) return;
    if (FT_New_Face(library_, font_path().c_str(), 0, &face_) != 0) face_ = nullptr;
  }
  ~Face() {
    if (face_) FT_Done_Face(face_);
    if (library_) FT_Done_FreeType(library_);
  }
  Face(const Face&) = delete;
  Face& operator=(const Face&) = delete;
  bool ok() const { return face_ != nullptr; }

  const Glyph& glyph(char32_t code, int px) {
    const std::uint64_t key = (static_cast<std::uint64_t>(px) << 32) | code;
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    Glyph g;
    if (FT_Set_Pixel_Sizes(face_, 0, static_cast<FT_UInt>(px)) == 0 &&
        FT_Load_Char(face_, code, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) == 0) {
      const FT_GlyphSlot slot = face_->glyph;
      const FT_Bitmap& bm = slot->bitmap;
      g.width = static_cast<int>(bm.width);
      g.rows = static_cast<int>(bm.rows);
      g.left = slot->bitmap_left;
      g.top = slot->bitmap_top;
      g.advance = static_cast<int>((slot->advance.x + 32) >> 6);
      g.coverage.resize(static_cast<std::size_t>(g.width) * g.rows);
      for (int r = 0; r < g.rows; ++r) {
        std::copy_n(bm.buffer + static_cast<std::ptrdiff_t>(r) * bm.pitch, g.width, &g.coverage[static_cast<std::size_t>(r) * g.width]);
      }
    }
    // A cache that only grows with distinct (character, size) pairs: a few hundred at most.
    if (cache_.size() > 4096) cache_.clear();
    return cache_.emplace(key, std::move(g)).first->second;
  }

 private:
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  std::unordered_map<std::uint64_t, Glyph> cache_;
};

Face& face() {
  thread_local Face f;
  return f;
}

// UTF-8 to code points; a broken sequence reads as '?'.
std::u32string decode_utf8(std::string_view s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (n == 0 || i + n > s.size()) {
      out.push_back(U'?');
      ++i;
      continue;
    }
    char32_t cp = n == 1 ? c : c & (0x7F >> n);
    bool ok = true;
    for (int k = 1; k < n; ++k) {
      const auto cc = static_cast<unsigned char>(s[i + k]);
      ok = ok && (cc >> 6) == 2;
      cp = (cp << 6) | (cc & 0x3F);
    }
    out.push_back(ok ? cp : U'?');
    i += ok ? n : 1;
  }
  return out;
}

// The em size's ascent (DejaVu Sans: 0.93 em above the baseline, 0.24 below).
int ascent_px(int px) { return static_cast<int>(std::lround(0.93 * px)); }

int bitmap_dot(int px) { return std::max(1, static_cast<int>(std::lround(px / 9.0))); }

void blend(std::uint8_t* p, Rgba c, int coverage) {
  const int a = coverage * c.a / 255;
  p[0] = static_cast<std::uint8_t>(p[0] + (c.r - p[0]) * a / 255);
  p[1] = static_cast<std::uint8_t>(p[1] + (c.g - p[1]) * a / 255);
  p[2] = static_cast<std::uint8_t>(p[2] + (c.b - p[2]) * a / 255);
  p[3] = 255;
}

// Lays out (and, with `rgba`, draws) the text; the box it covers.
TextBox run(std::span<std::uint8_t> rgba, ImageSize size, std::string_view text, int x, int y, int px, Rgba colour) {
  const bool draw = rgba.size() >= rgba_bytes(size) && size.width > 0 && size.height > 0;
  const int line = line_height_px(px);
  TextBox box{x, y, x, y};
  int pen = x, top = y, lines = 1;
  Face& f = face();
  if (!f.ok()) {
    // The 5x7 bitmap fallback: upper case, dot-sized blocks.
    const int dot = bitmap_dot(px);
    for (char c : text) {
      if (c == '\n') {
        pen = x, top += line, ++lines;
        continue;
      }
      const auto rows = glyph_rows(c);
      for (int r = 0; draw && r < kGlyphHeight; ++r) {
        for (int col = 0; col < kGlyphWidth; ++col) {
          if (!(rows[r] & (0x10 >> col))) continue;
          for (int py = std::max(0, top + r * dot); py < std::min(size.height, top + (r + 1) * dot); ++py) {
            for (int qx = std::max(0, pen + col * dot); qx < std::min(size.width, pen + (col + 1) * dot); ++qx) {
              blend(&rgba[(static_cast<std::size_t>(py) * size.width + qx) * 4], colour, 255);
            }
          }
        }
      }
      pen += kGlyphAdvance * dot;
      box.right = std::max(box.right, pen);
    }
    box.bottom = y + (lines - 1) * line + kGlyphHeight * dot;
    return box;
  }
  for (char32_t c : decode_utf8(text)) {
    if (c == U'\n') {
      pen = x, top += line, ++lines;
      continue;
    }
    const Glyph& g = f.glyph(c, px);
    const int baseline = top + ascent_px(px);
    for (int r = 0; draw && r < g.rows; ++r) {
      const int py = baseline - g.top + r;
      if (py < 0 || py >= size.height) continue;
      for (int col = 0; col < g.width; ++col) {
        const int qx = pen + g.left + col;
        const int cover = g.coverage[static_cast<std::size_t>(r) * g.width + col];
        if (qx < 0 || qx >= size.width || cover == 0) continue;
        blend(&rgba[(static_cast<std::size_t>(py) * size.width + qx) * 4], colour, cover);
      }
    }
    pen += g.advance;
    box.right = std::max(box.right, pen);
  }
  box.bottom = y + (lines - 1) * line + static_cast<int>(std::lround(1.17 * px));
  return box;
}

}  // namespace

int line_height_px(int px) { return static_cast<int>(std::lround(1.25 * px)); }

bool vector_font_available() { return face().ok(); }

TextBox blit_text(std::span<std::uint8_t> rgba, ImageSize size, std::string_view text, int x, int y, int px, Rgba colour) {
  return run(rgba, size, text, x, y, px, colour);
}

TextBox measure_text(std::string_view text, int x, int y, int px) { return run({}, {0, 0}, text, x, y, px, {}); }

}  // namespace softtune::render
