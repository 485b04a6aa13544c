#include "app/accuracy_app.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "app/accuracy_cost.h"
#include "app/stability_app.h"
#include "box2d_spring.h"
#include "plot/csv_writer.h"
#include "plot/svg_writer.h"
#include "softtune/analytic.h"
#include "softtune/designer.h"
#include "softtune/discrete_analysis.h"

namespace softtune::app {

using nlohmann::json;
using codec::AccuracyRequest;
using codec::row_label;

AccuracyReport run_accuracy_report(const AccuracyRequest& q, const std::optional<EngineRunner>& engine,
                                   const SecondsClock& clock) {
  require_within_budget(accuracy_cost(q, engine.has_value(), false));
  AccuracySettings s = q.settings;
  s.clock = clock;
  if (q.box2d) s.engine = engine;
  return run_accuracy(s);
}

json run_accuracy(const json& doc, const std::optional<EngineRunner>& engine) {
  const AccuracyRequest q = codec::decode_accuracy_request(doc);
  const AccuracyReport report = run_accuracy_report(q, engine);
  return codec::encode_accuracy_report(q, report, q.box2d && engine.has_value());
}

EngineRunner box2d_row() { return EngineRunner{kBox2DRowName, run_box2d_spring}; }

Answer accuracy_answer(const json& request, Format format) {
  const AccuracyRequest q = codec::decode_accuracy_request(request);
  require_within_budget(accuracy_cost(q, true, format == Format::svg));
  const AccuracyReport report = run_accuracy_report(q, box2d_row());
  Answer a;
  a.format = format;
  if (format == Format::svg) {
    a.text = accuracy_svg(q, report);
    return a;
  }
  json encoded = codec::encode_accuracy_report(q, report, q.box2d);
  if (format == Format::csv) {
    a.text = accuracy_csv(encoded);
  } else {
    a.json = std::move(encoded);
  }
  return a;
}

std::string accuracy_csv(const json& encoded) {
  const std::vector<std::string> header = {
      "method", "fps", "substeps", "h", "frames", "max_error", "rms_error", "achieved_frequency_hz_poles",
      "achieved_frequency_hz_trajectory", "achieved_damping_ratio_poles", "achieved_damping_ratio_trajectory",
      "spectral_radius", "blew_up", "cpu_seconds_per_sim_second"};
  auto text = [](const json& v) -> std::string {
    if (v.is_null()) return "";
    if (v.is_string()) return v.get<std::string>();
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_number_float()) {
      // Shortest text that reads back as the same double (60.0 -> "60").
      char buffer[32];
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, v.get<double>()).ptr;
      return std::string(buffer, end);
    }
    return v.dump();
  };
  std::vector<std::vector<std::string>> cells;
  for (const json& row : encoded.at("rows")) {
    std::vector<std::string> line;
    for (const std::string& column : header) {
      const auto split = column.rfind('_');
      const std::string parent = column.substr(0, split), child = column.substr(split + 1);
      if (!row.contains(column) && row.contains(parent) && row.at(parent).is_object()) {
        line.push_back(text(row.at(parent).at(child)));
      } else {
        line.push_back(text(row.at(column)));
      }
    }
    cells.push_back(std::move(line));
  }
  return plot::render_csv(header, cells);
}

namespace {

using plot::Axis;
using plot::Plot;
using plot::Scale;
using plot::Series;
using plot::Style;

bool in_response(const AccuracyRow& row, const AccuracyRequest& q) {
  return row.fps == q.tune.fps && row.substeps == 1;
}

Plot response_plot(const AccuracyRequest& q, const AccuracyReport& report) {
  const AccuracySettings& s = q.settings;
  Plot p{"Response at " + fmt::format("{:g} fps", q.tune.fps) + ": every method against the exact solution",
         plot::make_axis("time", "s"), plot::make_axis("position", "m"), {}, {}};
  Series exact{"exact", "m", {}, {}, Style::line, true};
  const int samples = 400;
  for (int i = 0; i <= samples; ++i) {
    const double t = report.duration_s * i / samples;
    exact.x.push_back(t);
    exact.y.push_back(analytic_state({kStandardX0, 0.0}, s.omega, s.damping_ratio, t).x);
  }
  bool wild = false;
  for (const AccuracyRow& row : report.rows) {
    if (!in_response(row, q)) continue;
    Series series{row_label(row), "m", {}, {}, Style::line_and_markers, false};
    for (std::size_t n = 0; n < row.positions.size(); ++n) {
      series.x.push_back(static_cast<double>(n) / row.fps);
      series.y.push_back(row.positions[n]);
      wild = wild || std::abs(row.positions[n]) > 2.0 * kStandardX0;
    }
    p.series.push_back(std::move(series));
  }
  p.series.push_back(std::move(exact));
  if (wild) {
    // A blown-up run would flatten every other curve: show +-2 amplitudes and let it leave the box.
    p.y.min = -2.0 * kStandardX0;
    p.y.max = 2.0 * kStandardX0;
    p.title += " (y clipped to +-2)";
  }
  return p;
}

Plot error_plot(const AccuracyRequest& q, const AccuracyReport& report) {
  const AccuracySettings& s = q.settings;
  Plot p{"Error over time at " + fmt::format("{:g} fps", q.tune.fps) + " (|x - exact| / x0; dashed: budget)", plot::make_axis("time", "s"),
         plot::make_axis("position error", "fraction of x0", Scale::log, 1e-8, 1e3), {}, {s.error_budget}};
  for (const AccuracyRow& row : report.rows) {
    if (!in_response(row, q)) continue;
    Series series{row_label(row), "", {}, {}, Style::line, false};
    for (std::size_t n = 1; n < row.positions.size(); ++n) {
      const double t = static_cast<double>(n) / row.fps;
      series.x.push_back(t);
      series.y.push_back(std::abs(row.positions[n] - analytic_state({kStandardX0, 0.0}, s.omega, s.damping_ratio, t).x) /
                         kStandardX0);
    }
    p.series.push_back(std::move(series));
  }
  return p;
}

Plot work_precision_plot(const AccuracyRequest& q, const AccuracyReport& report) {
  Plot p{"Work-precision: max error against CPU time (dashed: budget)", plot::make_axis("CPU time per simulated second", "s", Scale::log),
         plot::make_axis("max position error", "fraction of x0", Scale::log), {}, {q.settings.error_budget}};
  // One series per configuration (method and substeps) across the frame rates.
  for (const AccuracyRow& row : report.rows) {
    const std::string label = row_label(row);
    auto it = std::find_if(p.series.begin(), p.series.end(), [&](const Series& s) { return s.name == label; });
    if (it == p.series.end()) {
      p.series.push_back({label, "", {}, {}, Style::line_and_markers, false});
      it = p.series.end() - 1;
    }
    if (row.blew_up || !row.max_error) continue;
    it->x.push_back(row.cpu_seconds_per_sim_second);
    it->y.push_back(*row.max_error);
  }
  return p;
}

}  // namespace

std::string accuracy_svg(const AccuracyRequest& q, const AccuracyReport& report) {
  return plot::render_svg(std::vector<Plot>{response_plot(q, report), error_plot(q, report), work_precision_plot(q, report),
                                            stability_map_plot(q.settings.damping_ratio)});
}

}  // namespace softtune::app
