#pragma once
// A check report as JUnit XML, the test report GitLab, Jenkins and GitHub Actions show: one <testsuite> per
// preset, one <testcase> per rate ("60 fps x 1"), a <failure> naming each failed expectation or drift with
// its figures, an <error> for a preset that could not run. The structure follows the JUnit XSD Jenkins and
// GitLab read (testsuites > testsuite > testcase > failure | error, with tests, failures, errors and time
// agreeing with the cases inside); docs/preset-ci.md.

#include <string>
#include <string_view>

#include "app/check_app.h"

namespace softtune::app {

/// `text` escaped for an XML attribute or element: & < > " ' as entities, control characters other than
/// tab and newline dropped (XML 1.0 cannot carry them at all).
std::string xml_escaped(std::string_view text);

/// The report as a JUnit XML document.
std::string junit_xml(const CheckReport& report);

}  // namespace softtune::app
