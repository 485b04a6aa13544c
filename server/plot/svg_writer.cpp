#include "plot/svg_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "softtune/support/xml_escape.h"

namespace softtune::plot {
namespace {

// Panel layout (px): plot area, legend column to its right.
constexpr double kLeft = 84, kTop = 44, kPlotWidth = 470, kPlotHeight = 276;
constexpr double kLegendX = kLeft + kPlotWidth + 18;
constexpr const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
                                    "#e377c2", "#17becf", "#7f7f7f", "#bcbd22", "#393b79", "#637939"};
constexpr int kPaletteSize = sizeof(kPalette) / sizeof(kPalette[0]);

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2f", v);
  return b;
}

std::string tick_label(double v) {
  char b[32];
  if (v != 0.0 && (std::abs(v) < 1e-3 || std::abs(v) >= 1e5)) {
    std::snprintf(b, sizeof b, "%.0e", v);
  } else {
    std::snprintf(b, sizeof b, "%g", v);
  }
  return b;
}

bool usable(double v, Scale s) { return std::isfinite(v) && (s == Scale::linear || v > 0.0); }

// Axis range in data units, from the fixed limits or the data (with a margin for linear axes).
struct Range {
  double lo, hi;
};

Range axis_range(const Axis& axis, const std::vector<double>& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values) {
    if (!usable(v, axis.scale)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (axis.min) lo = *axis.min;
  if (axis.max) hi = *axis.max;
  if (!(lo <= hi)) return axis.scale == Scale::log ? Range{1.0, 10.0} : Range{0.0, 1.0};
  if (axis.scale == Scale::log) {
    if (lo == hi) return {lo / 10.0, hi * 10.0};
    return {axis.min ? lo : std::pow(10.0, std::floor(std::log10(lo))),
            axis.max ? hi : std::pow(10.0, std::ceil(std::log10(hi)))};
  }
  if (lo == hi) return {lo - 1.0, hi + 1.0};
  const double pad = 0.05 * (hi - lo);
  return {axis.min ? lo : lo - pad, axis.max ? hi : hi + pad};
}

// Fraction 0..1 along the axis.
double fraction(double v, const Range& r, Scale s) {
  if (s == Scale::log) return (std::log10(v) - std::log10(r.lo)) / (std::log10(r.hi) - std::log10(r.lo));
  return (v - r.lo) / (r.hi - r.lo);
}

// Tick values: "nice" steps (1, 2, 5 x 10^k) on a linear axis, decades on a log axis.
std::vector<double> ticks(const Range& r, Scale s) {
  std::vector<double> out;
  if (s == Scale::log) {
    const int first = static_cast<int>(std::ceil(std::log10(r.lo) - 1e-9));
    const int last = static_cast<int>(std::floor(std::log10(r.hi) + 1e-9));
    const int stride = std::max(1, (last - first) / 8 + 1);
    for (int e = first; e <= last; e += stride) out.push_back(std::pow(10.0, e));
    return out;
  }
  const double raw = (r.hi - r.lo) / 6.0;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / mag;
  const double step = (norm < 1.5 ? 1.0 : norm < 3.5 ? 2.0 : norm < 7.5 ? 5.0 : 10.0) * mag;
  for (double v = std::ceil(r.lo / step) * step; v <= r.hi + 1e-9 * step; v += step) {
    out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return out;
}

std::string axis_title(const Axis& a) {
  std::string t = a.label;
  if (!a.unit.empty()) t += " (" + a.unit + ")";
  if (a.scale == Scale::log) t += ", log scale";
  return t;
}

// Where one panel's data lands: its axis ranges in data units and its top edge in the SVG.
struct PanelFrame {
  const Plot& p;
  Range rx, ry;
  double y0, top;
  double px(double v) const { return kLeft + kPlotWidth * fraction(v, rx, p.x.scale); }
  double py(double v) const { return top + kPlotHeight * (1.0 - fraction(v, ry, p.y.scale)); }
};

// The axis ranges cover every usable point of every series and the reference lines.
PanelFrame panel_frame(const Plot& p, double y0) {
  std::vector<double> xs, ys;
  for (const Series& s : p.series) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (usable(s.x[i], p.x.scale) && usable(s.y[i], p.y.scale)) {
        xs.push_back(s.x[i]);
        ys.push_back(s.y[i]);
      }
    }
  }
  for (double r : p.y_references) ys.push_back(r);
  return {p, axis_range(p.x, xs), axis_range(p.y, ys), y0, y0 + kTop};
}

// Title, the plot box and the clip path the series are drawn through.
void draw_box(std::ostringstream& o, const PanelFrame& f, int index) {
  o << "<text x=\"" << num(kLeft + kPlotWidth / 2) << "\" y=\"" << num(f.y0 + 26)
    << "\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">" << support::xml_escape(f.p.title) << "</text>\n";
  o << "<clipPath id=\"clip" << index << "\"><rect x=\"" << num(kLeft) << "\" y=\"" << num(f.top) << "\" width=\""
    << num(kPlotWidth) << "\" height=\"" << num(kPlotHeight) << "\"/></clipPath>\n";
  o << "<rect x=\"" << num(kLeft) << "\" y=\"" << num(f.top) << "\" width=\"" << num(kPlotWidth) << "\" height=\""
    << num(kPlotHeight) << "\" fill=\"#ffffff\" stroke=\"#333333\"/>\n";
}

// Grid lines, tick labels and both axis titles.
void draw_axes(std::ostringstream& o, const PanelFrame& f) {
  const Plot& p = f.p;
  const double top = f.top;
  for (double t : ticks(f.rx, p.x.scale)) {
    const double x = f.px(t);
    o << "<line x1=\"" << num(x) << "\" y1=\"" << num(top) << "\" x2=\"" << num(x) << "\" y2=\"" << num(top + kPlotHeight)
      << "\" stroke=\"#e3e3e3\"/>\n";
    o << "<text x=\"" << num(x) << "\" y=\"" << num(top + kPlotHeight + 16)
      << "\" text-anchor=\"middle\" font-size=\"11\">" << tick_label(t) << "</text>\n";
  }
  for (double t : ticks(f.ry, p.y.scale)) {
    const double y = f.py(t);
    o << "<line x1=\"" << num(kLeft) << "\" y1=\"" << num(y) << "\" x2=\"" << num(kLeft + kPlotWidth) << "\" y2=\"" << num(y)
      << "\" stroke=\"#e3e3e3\"/>\n";
    o << "<text x=\"" << num(kLeft - 6) << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\" font-size=\"11\">"
      << tick_label(t) << "</text>\n";
  }
  o << "<text x=\"" << num(kLeft + kPlotWidth / 2) << "\" y=\"" << num(top + kPlotHeight + 36)
    << "\" text-anchor=\"middle\" font-size=\"13\">" << support::xml_escape(axis_title(p.x)) << "</text>\n";
  const double ymid = top + kPlotHeight / 2;
  o << "<text x=\"18\" y=\"" << num(ymid) << "\" text-anchor=\"middle\" font-size=\"13\" transform=\"rotate(-90 18 "
    << num(ymid) << ")\">" << support::xml_escape(axis_title(p.y)) << "</text>\n";
}

// Reference lines and every series (lines broken at unusable points, markers), inside the clip path.
void draw_series(std::ostringstream& o, const PanelFrame& f, int index) {
  const Plot& p = f.p;
  o << "<g clip-path=\"url(#clip" << index << ")\">\n";
  for (double r : p.y_references) {
    if (!usable(r, p.y.scale)) continue;
    o << "<line x1=\"" << num(kLeft) << "\" y1=\"" << num(f.py(r)) << "\" x2=\"" << num(kLeft + kPlotWidth) << "\" y2=\""
      << num(f.py(r)) << "\" stroke=\"#555555\" stroke-dasharray=\"6 4\"/>\n";
  }
  for (std::size_t k = 0; k < p.series.size(); ++k) {
    const Series& s = p.series[k];
    const char* color = kPalette[k % kPaletteSize];
    const bool line = s.style != Style::markers, markers = s.style != Style::line;
    std::string points;
    auto flush = [&] {
      if (line && !points.empty()) {
        o << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.8\"" << (s.dashed ? " stroke-dasharray=\"5 3\"" : "")
          << " points=\"" << points << "\"/>\n";
      }
      points.clear();
    };
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!usable(s.x[i], p.x.scale) || !usable(s.y[i], p.y.scale)) {
        flush();
        continue;
      }
      // Far outside the box: keep the polyline's coordinates bounded (the clip path hides the rest).
      const double x = std::clamp(f.px(s.x[i]), -1e4, 1e4), y = std::clamp(f.py(s.y[i]), -1e4, 1e4);
      points += num(x) + "," + num(y) + " ";
      if (markers) o << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"3\" fill=\"" << color << "\"/>\n";
    }
    flush();
  }
  o << "</g>\n";
}

// Legend: one row per series, to the right of the plot area.
void draw_legend(std::ostringstream& o, const PanelFrame& f) {
  double ly = f.top + 8;
  for (std::size_t k = 0; k < f.p.series.size(); ++k) {
    const char* color = kPalette[k % kPaletteSize];
    o << "<line x1=\"" << num(kLegendX) << "\" y1=\"" << num(ly) << "\" x2=\"" << num(kLegendX + 20) << "\" y2=\"" << num(ly)
      << "\" stroke=\"" << color << "\" stroke-width=\"3\"" << (f.p.series[k].dashed ? " stroke-dasharray=\"5 3\"" : "") << "/>\n";
    o << "<text x=\"" << num(kLegendX + 26) << "\" y=\"" << num(ly + 4) << "\" font-size=\"11\">"
      << support::xml_escape(f.p.series[k].name) << "</text>\n";
    ly += 16;
  }
}

void panel(std::ostringstream& o, const Plot& p, double y0, int index) {
  const PanelFrame f = panel_frame(p, y0);
  draw_box(o, f, index);
  draw_axes(o, f);
  draw_series(o, f, index);
  draw_legend(o, f);
}

}  // namespace

std::string render_svg(const std::vector<Plot>& plots) {
  std::ostringstream o;
  const int height = kPanelHeight * static_cast<int>(std::max<std::size_t>(1, plots.size()));
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kPanelWidth << "\" height=\"" << height
    << "\" viewBox=\"0 0 " << kPanelWidth << ' ' << height << "\" font-family=\"sans-serif\">\n";
  o << "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  for (std::size_t i = 0; i < plots.size(); ++i) panel(o, plots[i], static_cast<double>(i) * kPanelHeight, static_cast<int>(i));
  o << "</svg>\n";
  return o.str();
}

std::string render_svg(const Plot& plot) { return render_svg(std::vector<Plot>{plot}); }

}  // namespace softtune::plot
