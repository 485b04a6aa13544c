#pragma once
// SVG for the plot model: axes with ticks and units, a grid, a legend, log or linear scales. No
// dependencies; the output is a standalone SVG document.

#include <string>
#include <vector>

#include "plot/plot_model.h"

namespace softtune::plot {

/// Pixel size of one plot panel.
inline constexpr int kPanelWidth = 760, kPanelHeight = 380;

/// One plot as a standalone SVG document.
std::string render_svg(const Plot& plot);

/// Several plots stacked vertically in one SVG document.
std::string render_svg(const std::vector<Plot>& plots);

}  // namespace softtune::plot
