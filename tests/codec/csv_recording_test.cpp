// The CSV reader of recordings: header names, separators, comments, and each bad row named by its row and
// column (a 422 whose detail gives the line number).
#include "codec/csv_recording.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

std::string refusal(const std::string& csv) {
  try {
    read_csv_recording(csv, "csv");
  } catch (const Problem& p) {
    return std::to_string(p.status) + " " + p.field;
  }
  return "accepted";
}

TEST(CsvRecording, ReadsNamedColumnsWithAnySeparator) {
  const NamedRecording r = read_csv_recording("# from Godot\ntime\tx\tangle\n0\t1\t2\n\n0.5\t1.5\t2.5\r\n", "csv");
  EXPECT_EQ(r.time_name, "time");
  ASSERT_EQ(r.probe_names, (std::vector<std::string>{"x", "angle"}));
  EXPECT_EQ(r.recording.time_s, (std::vector<double>{0, 0.5}));
  EXPECT_EQ(r.recording.probes[1], (std::vector<double>{2, 2.5}));
  EXPECT_EQ(read_csv_recording("t;x\n0;1\n1;2\n", "csv").recording.probes[0][1], 2.0);
}

TEST(CsvRecording, BadRowsAreNamedByRowAndColumn) {
  EXPECT_EQ(refusal("t,x\n0,1\n1,nan\n"), "422 csv.rows.1.x");
  EXPECT_EQ(refusal("t,x\n0,1\n1,1e999\n"), "422 csv.rows.1.x");
  EXPECT_EQ(refusal("t,x\n0,1\n1\n"), "422 csv.rows.1");
  EXPECT_EQ(refusal("t,x\n0,1\n0,2\n"), "422 csv.rows.1.t");
  EXPECT_EQ(refusal("t,x\n0,1\n"), "422 csv.rows.1.t");  // one row
  EXPECT_EQ(refusal("1,2\n3,4\n"), "422 csv.header");
  EXPECT_EQ(refusal("t,x,x\n"), "422 csv.header");
  EXPECT_EQ(refusal("t\n0\n1\n"), "422 csv.header");
  EXPECT_EQ(refusal(""), "422 csv");
  EXPECT_EQ(refusal(std::string(kCsvMaxBytes + 1, '1')), "422 csv");
}

}  // namespace
}  // namespace softtune::codec
