// docs/accuracy-and-stability.md's chain tables and its "blows up above f h = X" sentence are the code's
// bisected limits (docs/conventions.md, "Docs beside the code").
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "softtune/chain_solvers.h"
#include "softtune/sequential_impulse.h"

namespace softtune {
namespace {

std::string doc_text() {
  std::ifstream in(std::string(SOFTTUNE_SOURCE_DIR) + "/docs/accuracy-and-stability.md");
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// "none", or the bisected stable side at 3 significant digits.
void expect_cell(const std::string& cell, const ChainLimit& l, const std::string& where) {
  if (cell == "none") {
    EXPECT_EQ(l.kind, LimitKind::none_in_range) << where;
    return;
  }
  ASSERT_EQ(l.kind, LimitKind::found) << where << " doc says " << cell;
  EXPECT_NEAR(std::stod(cell) / *l.highest_stable_frequency_ratio, 1.0, 5e-3) << where;
}

TEST(ChainDocs, TablesAreTheBisectedLimits) {
  const std::string text = doc_text();
  const auto begin = text.find("<!-- chain-limits:begin -->"), end = text.find("<!-- chain-limits:end -->");
  ASSERT_NE(begin, std::string::npos);
  ASSERT_NE(end, std::string::npos);
  const ChainSweepSettings s = default_chain_sweep_settings();
  std::istringstream lines(text.substr(begin, end - begin));
  std::string line;
  std::optional<ChainSolver> solver;
  int rows = 0;
  const std::regex heading("^`([a-z0-9_]+)`");
  for (std::smatch m; std::getline(lines, line);) {
    if (std::regex_search(line, m, heading)) {
      solver = chain_solver_from_name(m[1].str());
      ASSERT_TRUE(solver) << line;
      continue;
    }
    if (!solver || line.rfind("| ", 0) != 0 || line.rfind("| mass", 0) == 0) continue;
    std::vector<std::string> cells;
    std::stringstream row(line.substr(1));
    for (std::string cell; std::getline(row, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      if (!cell.empty()) cells.push_back(cell);
    }
    ASSERT_EQ(cells.size(), 1 + s.iterations.size()) << line;
    const double ratio = std::stod(cells[0]);
    for (std::size_t i = 0; i < s.iterations.size(); ++i) {
      const ChainLimit l = find_chain_limit(*solver, s.iterations[i], true, ratio, 0.0, s.h, s.frequency_ratios, 1000);
      expect_cell(cells[i + 1], l, std::string(chain_solver_name(*solver)) + " ratio " + cells[0] + " count " +
                                       std::to_string(s.iterations[i]));
    }
    ++rows;
  }
  EXPECT_EQ(rows, 4 * static_cast<int>(s.mass_ratios.size()));
}

// "blows up above f h = 0.225 with one iteration (13.5 Hz at 60 fps; the 16-point grid alone said 0.159"
TEST(ChainDocs, TheBlowUpSentenceIsMeasured) {
  const std::string text = doc_text();
  std::smatch m;
  const std::regex sentence(R"(blows up\s+above f h = ([0-9.]+) with one iteration \(([0-9.]+) Hz at 60 fps; the 16-point grid alone said ([0-9.]+))");
  ASSERT_TRUE(std::regex_search(text, m, sentence));
  const ChainSweepSettings s = default_chain_sweep_settings();
  const ChainLimit l = find_chain_limit(ChainSolver::box2d_v2_4, 1, true, 1e6, 0.0, s.h, s.frequency_ratios, 1000);
  ASSERT_EQ(l.kind, LimitKind::found);
  EXPECT_NEAR(std::stod(m[1].str()) / *l.highest_stable_frequency_ratio, 1.0, 5e-3);
  EXPECT_NEAR(std::stod(m[2].str()) / *l.highest_stable_frequency_hz, 1.0, 5e-3);
  EXPECT_NEAR(std::stod(m[3].str()) / *l.scan_highest_stable_frequency_ratio, 1.0, 5e-3);
}

}  // namespace
}  // namespace softtune
