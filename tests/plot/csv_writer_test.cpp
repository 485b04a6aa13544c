// The CSV writer (csv_writer.cpp) against RFC 4180: CRLF line ends, a header line, and cells holding a comma,
// quote or line break quoted with doubled quotes, so that every row parses back to the cells written.
#include "plot/csv_writer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace softtune::plot {
namespace {

using Rows = std::vector<std::vector<std::string>>;

// A reader written from RFC 4180 section 2 (not from the writer): records end in CRLF, a quoted field may hold
// commas, CRLF and doubled quotes.
Rows parse_csv(const std::string& text) {
  Rows rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        rows.back().back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        rows.back().back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().emplace_back();
    } else if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') {
      rows.emplace_back(1);
      ++i;
    } else {
      rows.back().back() += c;
    }
  }
  if (rows.back().size() == 1 && rows.back()[0].empty()) rows.pop_back();  // after the last CRLF
  return rows;
}

TEST(CsvWriter, QuotesWhatNeedsIt) {
  EXPECT_EQ(render_csv({"a", "b"}, {{"1", "x,y"}, {"say \"hi\"", ""}}), "a,b\r\n1,\"x,y\"\r\n\"say \"\"hi\"\"\",\r\n");
}

TEST(CsvWriter, RowsParseBackToTheCellsWritten) {
  const std::vector<std::string> header = {"method", "fps", "note"};
  const Rows rows = {{"soft", "60", ""},
                     {"explicit_euler", "120", "blew up, at frame 3"},
                     {"soft_exact", "30", "said \"exact\"\r\nthen a new line"},
                     {"implicit_euler", "1e+06", "\n"}};
  const std::string csv = render_csv(header, rows);
  EXPECT_EQ(csv.rfind("method,fps,note\r\n", 0), 0u);
  EXPECT_EQ(csv.substr(csv.size() - 2), "\r\n");
  const Rows back = parse_csv(csv);
  ASSERT_EQ(back.size(), rows.size() + 1);
  EXPECT_EQ(back[0], header);
  for (std::size_t i = 0; i < rows.size(); ++i) EXPECT_EQ(back[i + 1], rows[i]) << i;
}

TEST(CsvWriter, HeaderAloneWithoutRows) {
  EXPECT_EQ(render_csv({"x", "y"}, {}), "x,y\r\n");
}

}  // namespace
}  // namespace softtune::plot
