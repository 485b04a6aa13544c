#include "app/check_junit.h"

#include <cstdio>

namespace softtune::app {

namespace {

std::string seconds_text(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", s);
  return buffer;
}

std::string attribute(std::string_view name, std::string_view value) {
  return std::string(" ").append(name).append("=\"").append(xml_escaped(value)).append("\"");
}

// "60 fps x 1": the testcase's name within its preset's suite.
std::string rate_name(const CheckRate& r) {
  if (r.substeps == 0) return "load";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%g fps x %d", r.fps, r.substeps);
  return buffer;
}

std::string testcase_xml(const CaseResult& c) {
  std::string out = "    <testcase" + attribute("classname", "softtune.check." + c.preset) + attribute("name", rate_name(c.rate)) +
                    attribute("time", seconds_text(c.seconds));
  if (c.passed) return out + "/>\n";
  out += ">\n";
  const std::vector<std::string> messages = failure_messages(c);
  std::string body;
  for (const std::string& m : messages) body += m + "\n";
  const std::string first = messages.empty() ? "failed" : messages.front();
  const std::string summary = messages.size() > 1 ? first + " (and " + std::to_string(messages.size() - 1) + " more)" : first;
  const char* element = c.problem ? "error" : "failure";
  bool expectation_failed = false;
  for (const auto& e : c.expectations) expectation_failed = expectation_failed || !e["passed"].get<bool>();
  const char* type = c.problem ? "problem" : (expectation_failed ? "expectation" : "drift");
  out += std::string("      <") + element + attribute("message", summary) + attribute("type", type) + ">" + xml_escaped(body) +
         "</" + element + ">\n";
  return out + "    </testcase>\n";
}

}  // namespace

std::string xml_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const auto u = static_cast<unsigned char>(ch);
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (u < 0x20 && ch != '\t' && ch != '\n') break;
        out += ch;
    }
  }
  return out;
}

std::string junit_xml(const CheckReport& report) {
  // Suites in the report's order: each preset's cases are adjacent there.
  std::string suites;
  int tests = 0, failures = 0, errors = 0;
  double time = 0.0;
  for (std::size_t i = 0; i < report.cases.size();) {
    std::size_t end = i;
    int s_failures = 0, s_errors = 0;
    double s_time = 0.0;
    std::string cases;
    for (; end < report.cases.size() && report.cases[end].preset == report.cases[i].preset; ++end) {
      const CaseResult& c = report.cases[end];
      if (!c.passed) ++(c.problem ? s_errors : s_failures);
      s_time += c.seconds;
      cases += testcase_xml(c);
    }
    const int s_tests = static_cast<int>(end - i);
    suites += "  <testsuite" + attribute("name", "softtune.check." + report.cases[i].preset) + attribute("tests", std::to_string(s_tests)) +
              attribute("failures", std::to_string(s_failures)) + attribute("errors", std::to_string(s_errors)) +
              attribute("skipped", "0") + attribute("time", seconds_text(s_time)) + ">\n" + cases + "  </testsuite>\n";
    tests += s_tests;
    failures += s_failures;
    errors += s_errors;
    time += s_time;
    i = end;
  }
  const std::string name = "softtune check (shard " + std::to_string(report.shard.index) + "/" + std::to_string(report.shard.count) + ")";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites" + attribute("name", name) + attribute("tests", std::to_string(tests)) +
         attribute("failures", std::to_string(failures)) + attribute("errors", std::to_string(errors)) +
         attribute("time", seconds_text(time)) + ">\n" + suites + "</testsuites>\n";
}

}  // namespace softtune::app
