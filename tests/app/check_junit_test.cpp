// The JUnit report: valid against tests/app/junit.xsd (the structure Jenkins, GitLab and GitHub Actions
// read), parsed back with libxml2, its counts agree with its testcases, and its failures name the
// expectation and the figures.
#include "app/check_junit.h"

#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlschemas.h>

#include <map>

#include "app/preset_store.h"

namespace softtune::app {
namespace {

using nlohmann::json;

std::string attr(xmlNode* n, const char* name) {
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(name));
  std::string out = v ? reinterpret_cast<const char*>(v) : "";
  xmlFree(v);
  return out;
}

std::vector<xmlNode*> children(xmlNode* n, const std::string& name) {
  std::vector<xmlNode*> out;
  for (xmlNode* c = n->children; c; c = c->next) {
    if (c->type == XML_ELEMENT_NODE && name == reinterpret_cast<const char*>(c->name)) out.push_back(c);
  }
  return out;
}

// Empty when `xml` is valid against the XSD; libxml2's first complaint otherwise.
std::string schema_error(xmlDoc* doc) {
  xmlSchemaParserCtxt* parser = xmlSchemaNewParserCtxt(SOFTTUNE_SOURCE_DIR "/tests/app/junit.xsd");
  xmlSchema* schema = xmlSchemaParse(parser);
  xmlSchemaValidCtxt* valid = xmlSchemaNewValidCtxt(schema);
  std::string error;
  xmlSchemaSetValidStructuredErrors(valid, [](void* out, xmlError* e) { if (static_cast<std::string*>(out)->empty()) *static_cast<std::string*>(out) = e->message; }, &error);
  const int rc = schema ? xmlSchemaValidateDoc(valid, doc) : -1;
  if (rc != 0 && error.empty()) error = "validation failed (" + std::to_string(rc) + ")";
  xmlSchemaFreeValidCtxt(valid);
  xmlSchemaFree(schema);
  xmlSchemaFreeParserCtxt(parser);
  return error;
}

TEST(CheckJunit, TheReportIsValidJUnitAndParsesBack) {
  // A pass and a fail (oscillator at 60 and 30 fps with its 60 fps bounds forced on every rate), a drift and a
  // preset that cannot be read; a name with XML's special characters.
  json oscillator = load_preset(SOFTTUNE_PRESETS_DIR, "oscillator");
  for (json& e : oscillator["expectations"]) e.erase("fps");
  oscillator["expectations"][0]["note"] = "implicit Euler <lags> & \"damps\"";
  const json mouse = load_preset(SOFTTUNE_PRESETS_DIR, "mouse");
  Baseline baseline;
  baseline.cases["mouse@60x1"] = {{"drag.frequency_hz", 3.0}};
  CheckOptions o;
  o.fps = {30, 60};
  o.baseline = &baseline;
  const CheckReport report = run_checks({{"oscillator", oscillator, std::nullopt}, {"mouse", mouse, std::nullopt},
                                         {"a&b", json(), json{{"detail", "a&b.json: not <JSON>"}}}}, o);
  const std::string xml = junit_xml(report);

  xmlDoc* doc = xmlReadMemory(xml.data(), static_cast<int>(xml.size()), "report.xml", nullptr, XML_PARSE_NONET);
  ASSERT_NE(doc, nullptr) << xml;
  EXPECT_EQ(schema_error(doc), "") << xml;

  xmlNode* root = xmlDocGetRootElement(doc);
  ASSERT_STREQ(reinterpret_cast<const char*>(root->name), "testsuites");
  int tests = 0, failures = 0, errors = 0;
  std::map<std::string, xmlNode*> cases;  // "suite/testcase"
  for (xmlNode* suite : children(root, "testsuite")) {
    int t = 0, f = 0, e = 0;
    for (xmlNode* c : children(suite, "testcase")) {
      ++t;
      f += children(c, "failure").empty() ? 0 : 1;
      e += children(c, "error").empty() ? 0 : 1;
      EXPECT_EQ(attr(c, "classname"), attr(suite, "name"));
      cases[attr(suite, "name") + "/" + attr(c, "name")] = c;
    }
    EXPECT_EQ(std::stoi(attr(suite, "tests")), t) << attr(suite, "name");
    EXPECT_EQ(std::stoi(attr(suite, "failures")), f);
    EXPECT_EQ(std::stoi(attr(suite, "errors")), e);
    tests += t;
    failures += f;
    errors += e;
  }
  EXPECT_EQ(std::stoi(attr(root, "tests")), tests);
  EXPECT_EQ(std::stoi(attr(root, "failures")), failures);
  EXPECT_EQ(std::stoi(attr(root, "errors")), errors);
  EXPECT_EQ(tests, 5);  // one testcase per preset and rate; the unreadable one has one
  EXPECT_EQ(failures, 2);
  EXPECT_EQ(errors, 1);

  // Parsed back: the names and messages as written, special characters restored.
  ASSERT_TRUE(cases.contains("softtune.check.oscillator/60 fps x 1"));
  EXPECT_TRUE(children(cases["softtune.check.oscillator/60 fps x 1"], "failure").empty());
  ASSERT_TRUE(cases.contains("softtune.check.oscillator/30 fps x 1"));
  xmlNode* failure = children(cases["softtune.check.oscillator/30 fps x 1"], "failure").at(0);
  const std::string message = attr(failure, "message");
  EXPECT_EQ(message.rfind("soft.frequency_error = 0.1089, above max 0.08 (implicit Euler <lags> & \"damps\")", 0), 0u) << message;
  xmlChar* body = xmlNodeGetContent(failure);
  EXPECT_NE(std::string(reinterpret_cast<const char*>(body)).find("soft.damping_ratio_error = 0.1249, above max 0.1"), std::string::npos);
  xmlFree(body);
  xmlNode* drift = children(cases["softtune.check.mouse/60 fps x 1"], "failure").at(0);
  EXPECT_EQ(attr(drift, "message").rfind("drift drag.frequency_hz: baseline 3, now 2", 0), 0u) << attr(drift, "message");
  ASSERT_TRUE(cases.contains("softtune.check.a&b/load"));
  EXPECT_EQ(attr(children(cases["softtune.check.a&b/load"], "error").at(0), "message"), "a&b.json: not <JSON>");
  xmlFreeDoc(doc);
}

TEST(CheckJunit, EscapingDropsWhatXmlCannotCarry) {
  EXPECT_EQ(xml_escaped("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&apos;");
  EXPECT_EQ(xml_escaped(std::string("x\x01y\tz\n", 6)), "xy\tz\n");
}

}  // namespace
}  // namespace softtune::app
