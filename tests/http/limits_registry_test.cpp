// The limits registry (limits_registry.cpp): each published limit once, under a snake_case key, with the
// value of the constant that enforces it; integral limits are JSON integers (a client reading
// max_body_bytes wants 1048576, not 1048576.0); the Markdown table has a header, a separator and one
// four-cell line per row.
#include "http/limits_registry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "codec/json_reader.h"
#include "http/limits.h"

using nlohmann::json;
using namespace softtune::http;

TEST(LimitsRegistry, EveryKeyOnceWithAPositiveFiniteValue) {
  std::set<std::string> keys;
  for (const NumericLimit& l : numeric_limits()) {
    const std::string key(l.key);
    EXPECT_TRUE(keys.insert(key).second) << "twice: " << key;
    for (char c : key) EXPECT_TRUE(std::islower(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_') << key;
    EXPECT_TRUE(std::isfinite(l.value) && l.value > 0) << key;
  }
  const json j = limits_json();
  EXPECT_EQ(j.size(), keys.size());
  // Read back through the strict reader: a duplicated key would be refused.
  EXPECT_NO_THROW(softtune::codec::parse_json(j.dump()));
}

TEST(LimitsRegistry, IntegralLimitsAreIntegersWithTheEnforcedValue) {
  const json j = limits_json();
  for (const NumericLimit& l : numeric_limits()) {
    const json& v = j.at(std::string(l.key));
    if (l.value == std::floor(l.value)) {
      EXPECT_TRUE(v.is_number_integer()) << l.key << " = " << v;
    }
    EXPECT_DOUBLE_EQ(v.get<double>(), l.value) << l.key;
  }
  EXPECT_EQ(j.at("max_body_bytes").get<long long>(), static_cast<long long>(limits::kMaxBodyBytes));
  EXPECT_EQ(j.at("max_json_depth").get<long long>(), softtune::codec::kMaxJsonDepth);
  EXPECT_EQ(j.at("request_read_timeout_ms").get<long long>(), limits::kRequestReadTimeout.count());
  EXPECT_EQ(j.at("max_body_bytes").dump().find('.'), std::string::npos);
}

TEST(LimitsRegistry, MarkdownTableHasOneLinePerRow) {
  const std::vector<LimitRow> rows = limit_rows();
  ASSERT_FALSE(rows.empty());
  const std::string table = limits_table_markdown();
  ASSERT_FALSE(table.empty());
  EXPECT_EQ(table.back(), '\n');
  std::istringstream in(table);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), rows.size() + 2);
  EXPECT_EQ(lines[0], "| Cap | Value | Defined in | Above it |");
  EXPECT_EQ(lines[1], "| --- | --- | --- | --- |");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string& line = lines[i + 2];
    EXPECT_EQ(line.rfind("| " + rows[i].cap + " | " + rows[i].value + " | ", 0), 0u) << line;
    EXPECT_EQ(line.substr(line.size() - 2), " |") << line;
    for (const std::string* cell : {&rows[i].cap, &rows[i].value, &rows[i].defined_in, &rows[i].above}) EXPECT_FALSE(cell->empty()) << line;
  }
}
