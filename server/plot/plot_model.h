#pragma once
// A small plot model shared by the CLI and the HTTP API: named series with units on axes with a linear or
// log scale. Writers (svg_writer.h, csv) turn it into files; the API can also send it as data.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace softtune::plot {

enum class Scale { linear, log };

struct Axis {
  std::string label;  ///< e.g. "time"
  std::string unit;   ///< e.g. "s"; empty for dimensionless
  Scale scale = Scale::linear;
  std::optional<double> min, max;  ///< fixed range; points outside are clipped. Empty: fit the data
};

enum class Style { line, markers, line_and_markers };

struct Series {
  std::string name;  ///< legend entry, e.g. "soft 60 fps"
  std::string unit;  ///< unit of y, e.g. "m" (the axis carries it too; kept for data consumers)
  std::vector<double> x, y;  ///< same length; non-finite points (and non-positive ones on a log axis) are skipped
  Style style = Style::line;
  bool dashed = false;
};

/// An axis in one expression.
inline Axis make_axis(std::string label, std::string unit, Scale scale = Scale::linear,
                      std::optional<double> min = std::nullopt, std::optional<double> max = std::nullopt) {
  Axis a;
  a.label = std::move(label);
  a.unit = std::move(unit);
  a.scale = scale;
  a.min = min;
  a.max = max;
  return a;
}

struct Plot {
  std::string title;
  Axis x, y;
  std::vector<Series> series;
  /// Optional horizontal reference line (e.g. the error budget or spectral radius 1), drawn dashed.
  std::vector<double> y_references;
};

}  // namespace softtune::plot
