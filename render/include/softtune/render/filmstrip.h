#pragma once
// A filmstrip (contact sheet): every Nth frame, shrunk, in a grid of numbered tiles, as one PNG.

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "softtune/render/png.h"
#include "softtune/render/view.h"

namespace softtune::render {

struct FilmstripLayout {
  int every = 1;       ///< frames 0, every, 2 every, ... appear
  int tiles = 1;
  int columns = 1;
  int rows = 1;
  int shrink = 1;      ///< a tile is the frame shrunk by this factor (box filter)
  ImageSize tile;
  ImageSize sheet;
  int gap_px = 4;
};

inline constexpr int kFilmstripTargetTiles = 10;   ///< when `every` is automatic
inline constexpr int kFilmstripColumns = 5;
inline constexpr int kFilmstripTileWidth = 160;    ///< px, about

/// The layout for `frames` frames of `frame` size showing every `every`th frame (0: automatic, about
/// kFilmstripTargetTiles tiles).
FilmstripLayout filmstrip_layout(int frames, int every, ImageSize frame);

/// The sheet being filled. place() of different frames may run concurrently: each writes its own tile.
class Filmstrip {
 public:
  explicit Filmstrip(const FilmstripLayout& layout);
  const FilmstripLayout& layout() const { return layout_; }
  /// Copies frame `index` (RGBA of `frame` size) into its tile, with its number, if it is one of the
  /// frames shown.
  void place(int index, std::span<const std::uint8_t> rgba, ImageSize frame);
  std::string encode(PngOptions options) const;
  std::span<const std::uint8_t> pixels() const { return pixels_; }

 private:
  FilmstripLayout layout_;
  std::vector<std::uint8_t> pixels_;  // RGBA, sheet size
};

}  // namespace softtune::render
