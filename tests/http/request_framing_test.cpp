#include "http/request_framing.h"

#include <gtest/gtest.h>

#include <string>

using softtune::http::head_size;
using softtune::http::is_lane_request;
using softtune::http::request_size;

// Named, not anonymous: the test sources are compiled together (unity builds), beside other helpers.
namespace request_framing_test {

constexpr std::size_t kMax = 1 << 20;

std::string post(const std::string& headers) { return "POST /api/v1/tune HTTP/1.1\r\nHost: t\r\n" + headers + "\r\n"; }


TEST(RequestFraming, TheHeadEndsAtTheBlankLine) {
  EXPECT_FALSE(head_size("GET / HTTP/1.1\r\nHost: t\r\n"));
  EXPECT_EQ(head_size("GET / HTTP/1.1\r\n\r\nrest"), 18u);
}

TEST(RequestFraming, ABodyWithOneContentLengthIsPartOfTheRequest) {
  const std::string head = post("Content-Length: 17\r\n");
  EXPECT_EQ(request_size(head, kMax), head.size() + 17);
  EXPECT_EQ(request_size(post("content-length:\t5 \r\n"), kMax), post("content-length:\t5 \r\n").size() + 5);
  EXPECT_EQ(request_size(post(""), kMax), post("").size());  // no body
  EXPECT_FALSE(request_size("POST / HTTP/1.1\r\nContent-Length: 17\r\n", kMax));  // head incomplete
}

// Heads the worker refuses before any body byte is read, or whose body it reads itself: the head alone.
TEST(RequestFraming, HeadsThatFrameNoBodyHereAreTheHeadAlone) {
  for (const std::string headers :
       {"Content-Length: 1048577\r\n", "Content-Length: 5\r\nContent-Length: 5\r\n", "Content-Length: 0x10\r\n",
        "Content-Length: -1\r\n", "Content-Length: 99999999999999999999999\r\n",
        "Transfer-Encoding: chunked\r\nContent-Length: 5\r\n", "Transfer-Encoding : chunked\r\nContent-Length: 5\r\n",
        "Content-Length : 5\r\n", "Expect: 100-continue\r\nContent-Length: 5\r\n", "NoColon\r\nContent-Length: 5\r\n"}) {
    EXPECT_EQ(request_size(post(headers), kMax), post(headers).size()) << headers;
  }
  EXPECT_EQ(request_size(post("Content-Length: 1048576\r\n"), kMax), post("Content-Length: 1048576\r\n").size() + kMax);
}

TEST(RequestFraming, HealthAndMetricsGoToTheLane) {
  EXPECT_TRUE(is_lane_request("GET /api/v1/health HTTP/1.1\r\n"));
  EXPECT_TRUE(is_lane_request("HEAD /metrics HTTP/1.1\r\nHost: t\r\n\r\n"));
  EXPECT_TRUE(is_lane_request("GET /api/v1/health?x=1 HTTP/1.1\r\n"));
  EXPECT_FALSE(is_lane_request("GET /api/v1/healthy HTTP/1.1\r\n"));
  EXPECT_FALSE(is_lane_request("POST /api/v1/health HTTP/1.1\r\n"));
  EXPECT_FALSE(is_lane_request("GET /api/v1/presets HTTP/1.1\r\n"));
  EXPECT_FALSE(is_lane_request("GET /metricsx HTTP/1.1\r\n"));
}

}  // namespace request_framing_test
