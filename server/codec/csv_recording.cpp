#include "codec/csv_recording.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r' || s.front() == '"')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '"')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line, char separator) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const std::size_t at = line.find(separator, start);
    out.push_back(trim(line.substr(start, at == std::string_view::npos ? std::string_view::npos : at - start)));
    if (at == std::string_view::npos) return out;
    start = at + 1;
    if (out.size() > kIdentifyMaxProbes + 1) return out;  // already too many: refused by the caller
  }
}

std::string quote_text(std::string_view s) {
  return "\"" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "...\"" : "\"");
}

}  // namespace

NamedRecording read_csv_recording(std::string_view text, const std::string& field) {
  if (text.size() > kCsvMaxBytes) throw invalid_field(field, "must be at most 8 MiB of CSV text");
  NamedRecording out;
  std::vector<std::string> names;
  char separator = ',';
  std::size_t line_number = 0, start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = trim(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    if (names.empty()) {
      if (line.find(',') == std::string_view::npos) separator = line.find('\t') != std::string_view::npos ? '\t' : ';';
      for (std::string_view name : split(line, separator)) {
        if (name.empty() || name.size() > kCsvMaxNameBytes) {
          throw invalid_field(field + ".header", "line " + std::to_string(line_number) +
                                                     ": every column needs a name of 1 to 64 characters");
        }
        for (const std::string& seen : names) {
          if (seen == name) throw invalid_field(field + ".header", "names column " + quote_text(name) + " twice");
        }
        names.emplace_back(name);
        if (name.front() == '-' || name.front() == '+' || name.front() == '.' || std::isdigit(static_cast<unsigned char>(name.front()))) {
          throw invalid_field(field + ".header", "line " + std::to_string(line_number) +
                                                     " must be a header row naming the columns (time first), got " + quote_text(line));
        }
      }
      if (names.size() < 2) throw invalid_field(field + ".header", "must name a time column and at least one probe column");
      if (names.size() > kIdentifyMaxProbes + 1) throw invalid_field(field + ".header", "must name at most 16 probe columns beside time");
      out.recording.probes.resize(names.size() - 1);
      continue;
    }
    const std::size_t row = out.recording.time_s.size();
    if (row >= kIdentifyMaxSamples) throw invalid_field(field, "must have at most 100000 rows");
    if (row * out.recording.probes.size() >= kIdentifyMaxCells) {
      throw invalid_field(field, "must hold at most 400000 values (rows x probe columns)");
    }
    const std::vector<std::string_view> cells = split(line, separator);
    const std::string where = field + ".rows." + std::to_string(row);
    if (cells.size() != names.size()) {
      throw invalid_field(where, "line " + std::to_string(line_number) + " has " + std::to_string(cells.size()) +
                                     " fields where the header names " + std::to_string(names.size()));
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      double v = 0.0;
      const auto [ptr, ec] = std::from_chars(cells[c].data(), cells[c].data() + cells[c].size(), v);
      if (ec != std::errc() || ptr != cells[c].data() + cells[c].size() || !std::isfinite(v)) {
        throw invalid_field(where + "." + names[c], "line " + std::to_string(line_number) + ", column " + std::to_string(c + 1) +
                                                        " (" + quote_text(names[c]) + "): must be a finite number, got " + quote_text(cells[c]));
      }
      (c == 0 ? out.recording.time_s : out.recording.probes[c - 1]).push_back(v);
    }
  }
  if (names.empty()) throw invalid_field(field, "must start with a header row naming the columns (time first)");
  if (auto e = validate_recording(out.recording)) {
    const std::size_t row = std::min(e->row, out.recording.time_s.size());
    throw invalid_field(field + ".rows." + std::to_string(row) + "." + names[std::min(e->column, names.size() - 1)],
                        "column " + quote_text(names[std::min(e->column, names.size() - 1)]) + " " + std::string(e->rule));
  }
  out.time_name = names.front();
  out.probe_names.assign(names.begin() + 1, names.end());
  return out;
}

}  // namespace softtune::codec
