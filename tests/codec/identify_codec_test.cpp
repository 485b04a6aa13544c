// The identify contract's decoding: JSON arrays and CSV text, the typed values, earlier rounds and their
// rules; and a text/csv body's query turned into the JSON request.
#include "codec/identify_codec.h"

#include <gtest/gtest.h>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

using nlohmann::json;

std::string refusal(const json& doc) {
  try {
    decode_identify_request(doc);
  } catch (const Problem& p) {
    return std::to_string(p.status) + " " + p.field;
  }
  return "accepted";
}

const json kSeries = {{"time_s", {0, 0.1, 0.2}}, {"probes", {{"x", {1, 0.5, 0.2}}}}};

TEST(IdentifyCodec, DecodesSeriesTypedAndPrevious) {
  json doc = kSeries;
  doc["request"] = {{"frequency_hz", 5}, {"damping_ratio", 0.5}, {"effective_mass", 2}};
  doc["typed"] = {{"k", 100}, {"c", 2}};
  doc["previous"] = json::array({{{"measured", {{"frequency_hz", 4}, {"damping_ratio", 0.6}}}, {"typed", {{"frequency_hz", 5}, {"damping_ratio", 0.5}}}}});
  const IdentifyRequest q = decode_identify_request(doc);
  EXPECT_EQ(q.recording.probe_names, std::vector<std::string>{"x"});
  ASSERT_TRUE(q.typed && q.typed->spring);
  EXPECT_EQ(q.typed->spring->stiffness, 100.0);
  ASSERT_EQ(q.previous.size(), 1u);
  EXPECT_EQ(q.previous[0].measured->frequency_hz, 4.0);
}

TEST(IdentifyCodec, RefusesNamingTheField) {
  EXPECT_EQ(refusal({{"probes", {{"x", {1, 2}}}}}), "422 time_s");
  EXPECT_EQ(refusal({{"time_s", {0, 1}}, {"probes", {{"x", {1, 2}}}}, {"csv", "t,x\n"}}), "422 csv");
  EXPECT_EQ(refusal({{"time_s", {0, 1}}, {"probes", {{"x", {1, 2, 3}}}}}), "422 probes.x.2");
  EXPECT_EQ(refusal({{"time_s", {0, 1}}, {"probes", json::object()}}), "422 probes");
  json bad = kSeries;
  bad["typed"] = {{"frequency_hz", -1}, {"damping_ratio", 0.5}};
  EXPECT_EQ(refusal(bad), "422 typed.frequency_hz");
  bad = kSeries;
  bad["previous"] = json::array({{{"measured", {{"frequency_hz", 4}, {"damping_ratio", 0.6}}}}});
  EXPECT_EQ(refusal(bad), "422 previous.0.typed");
  bad["previous"] = json::array({1, 2, 3, 4, 5});
  EXPECT_EQ(refusal(bad), "422 previous");
  bad = kSeries;
  bad["engine"] = std::string(65, 'a');
  EXPECT_EQ(refusal(bad), "422 engine");
}

// A correction may type a negative damping ratio (or c), so typed values take one back, down to -1; a
// measured ratio stays >= 0; negative_damping is a boolean.
TEST(IdentifyCodec, TypedRatioMayBeNegative) {
  json doc = kSeries;
  doc["typed"] = {{"frequency_hz", 8}, {"damping_ratio", -0.1}};
  doc["negative_damping"] = false;
  const IdentifyRequest q = decode_identify_request(doc);
  EXPECT_EQ(q.typed->response->damping_ratio, -0.1);
  EXPECT_FALSE(q.negative_damping);
  EXPECT_TRUE(decode_identify_request(kSeries).negative_damping);
  json bad = kSeries;
  bad["typed"] = {{"frequency_hz", 8}, {"damping_ratio", -1.5}};
  EXPECT_EQ(refusal(bad), "422 typed.damping_ratio");
  bad = kSeries;
  bad["negative_damping"] = "no";
  EXPECT_EQ(refusal(bad), "422 negative_damping");
  bad = kSeries;
  bad["request"] = {{"frequency_hz", 5}, {"damping_ratio", 0.5}, {"effective_mass", 2}};
  bad["previous"] = json::array({{{"measured", {{"frequency_hz", 4}, {"damping_ratio", -0.1}}}, {"typed", {{"frequency_hz", 5}, {"damping_ratio", 0.5}}}}});
  EXPECT_EQ(refusal(bad), "422 previous.0.measured.damping_ratio");
}

TEST(IdentifyCodec, CsvQueryBecomesTheRequest) {
  const json doc = identify_request_from_csv("t,x\n", {{"engine", "unity"}, {"frequency_hz", "5"}, {"oscillation", "some"},
                                                       {"typed_frequency_hz", "6"}});
  EXPECT_EQ(doc["engine"], "unity");
  EXPECT_EQ(doc["request"]["frequency_hz"], 5.0);
  EXPECT_EQ(doc["request"]["oscillation"], "some");
  EXPECT_EQ(doc["typed"]["frequency_hz"], 6.0);
  EXPECT_EQ(identify_request_from_csv("t,x\n", {{"negative_damping", "false"}})["negative_damping"], false);
}

}  // namespace
}  // namespace softtune::codec
