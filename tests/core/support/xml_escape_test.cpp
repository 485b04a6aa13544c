// xml_escape (core/include/softtune/support/xml_escape.h): the four characters XML text and attributes
// cannot hold as they are, and nothing else touched.
#include "softtune/support/xml_escape.h"

#include <gtest/gtest.h>

namespace softtune::support {
namespace {

TEST(XmlEscape, TheFourSpecialCharactersBecomeEntities) {
  EXPECT_EQ(xml_escape(R"(a<b & "c">d)"), "a&lt;b &amp; &quot;c&quot;&gt;d");
  EXPECT_EQ(xml_escape("chassis/x 'ok' \xce\xb6"), "chassis/x 'ok' \xce\xb6");
  EXPECT_EQ(xml_escape(""), "");
}

}  // namespace
}  // namespace softtune::support
