// Number lists in a request (list_reader.cpp): [30, 60] reads back as given; an empty, too long or
// non-array list is refused naming the field; a bad entry is refused naming the field with its index, and
// the rule quotes the bounds.
#include "codec/list_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "codec/json_reader.h"
#include "codec/problem.h"

using nlohmann::json;
using namespace softtune::codec;

namespace {

// The field a list at "step_rates" (1 to 4 numbers in [1, 1000] Hz) is refused with, or "" when accepted.
std::string refused_field(const json& list, bool integers = false) {
  const json doc = {{"step_rates", list}};
  ObjectReader r(doc, "");
  try {
    if (integers) read_integer_list(r, "step_rates", 4, 1, 1000);
    else read_number_list(r, "step_rates", 4, 1.0, 1000.0, "Hz");
  } catch (const Problem& p) {
    EXPECT_EQ(p.status, 422);
    return p.field;
  }
  return "";
}

}  // namespace

TEST(ListReader, ReadsTheListAsGiven) {
  const json doc = json::parse(R"({"step_rates": [30, 60], "substeps": [1, 8]})");
  ObjectReader r(doc, "");
  EXPECT_EQ(read_number_list(r, "step_rates", 4, 1.0, 1000.0, "Hz"), (std::vector<double>{30, 60}));
  EXPECT_EQ(read_integer_list(r, "substeps", 4, 1, 64), (std::vector<int>{1, 8}));
  EXPECT_FALSE(read_number_list(r, "absent", 4, 1.0, 1000.0, "Hz"));
  EXPECT_NO_THROW(r.finish());  // both lists were read
}

TEST(ListReader, RefusesNamingTheFieldAndTheEntry) {
  EXPECT_EQ(refused_field({30, nullptr, 60}), "step_rates.1");
  EXPECT_EQ(refused_field({30, "60"}), "step_rates.1");
  EXPECT_EQ(refused_field({0.5}), "step_rates.0");   // below the bound
  EXPECT_EQ(refused_field({30, 2000}), "step_rates.1");  // above it
  EXPECT_EQ(refused_field(json::array()), "step_rates");
  EXPECT_EQ(refused_field({1, 2, 3, 4, 5}), "step_rates");  // more than 4 entries
  EXPECT_EQ(refused_field(30), "step_rates");
  EXPECT_EQ(refused_field({1, 2.5}, true), "step_rates.1");  // not an integer
  EXPECT_EQ(refused_field({1, 2}, true), "");
}

TEST(ListReader, TheRuleQuotesTheBounds) {
  const json doc = {{"step_rates", {30, -1}}};
  ObjectReader r(doc, "accuracy");
  try {
    read_number_list(r, "step_rates", 4, 1.0, 1000.0, "Hz");
    FAIL();
  } catch (const Problem& p) {
    EXPECT_EQ(p.field, "accuracy.step_rates.1");
    EXPECT_EQ(p.detail, "must be an array of 1 to 4 finite numbers in [1, 1000] Hz");
  }
}
