// The connection gate on its own: where a request head ends, and how many connections it can hold
// under the process's file-descriptor limit (checked in child processes, which may lower the limit).
#include "http/connection_gate.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <cstdlib>

using softtune::http::AfterServe;
using softtune::http::ConnectionGate;
using softtune::http::GateOptions;
using softtune::http::head_complete;
using softtune::http::ReadyConnection;
using softtune::http::Refusal;

namespace {

ConnectionGate make_gate(std::size_t max_open) {
  GateOptions o;
  o.threads = 2;
  o.max_open = max_open;
  return ConnectionGate(
      o, [](ReadyConnection&) { return AfterServe::close; }, [](Refusal, std::string_view) { return std::string(); });
}

// Runs in a child: sets the descriptor limits, then exits 0 when the gate's capacity is `expected` and
// the soft limit now leaves the reserve (128 + 2 workers + 64 queued) free beyond it.
void expect_capacity_under_limit(rlim_t soft, rlim_t hard, std::size_t max_open, std::size_t expected) {
  rlimit r{soft, hard};
  if (::setrlimit(RLIMIT_NOFILE, &r) != 0) std::_Exit(2);
  const ConnectionGate gate = make_gate(max_open);
  if (::getrlimit(RLIMIT_NOFILE, &r) != 0) std::_Exit(3);
  std::_Exit(gate.capacity() == expected && r.rlim_cur >= expected + 128 + 2 + 64 ? 0 : 1);
}

}  // namespace

TEST(ConnectionGate, HeadEndsAtTheBlankLine) {
  EXPECT_FALSE(head_complete(""));
  EXPECT_FALSE(head_complete("GET / HTTP/1.1\r\nHost: x\r\n"));
  EXPECT_FALSE(head_complete("GET / HTTP/1.1\nHost: x\n\n"));  // bare LF: the library would not accept it either
  EXPECT_TRUE(head_complete("GET / HTTP/1.1\r\nHost: x\r\n\r\n"));
  EXPECT_TRUE(head_complete("POST / HTTP/1.1\r\nContent-Length: 2\r\n\r\n{}"));
}

TEST(ConnectionGate, HoldsWhatTheDescriptorLimitAllows) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  // Room enough: the asked number.
  EXPECT_EXIT(expect_capacity_under_limit(4096, 4096, 1024, 1024), ::testing::ExitedWithCode(0), "");
  // A low soft limit under a high hard one is raised to fit.
  EXPECT_EXIT(expect_capacity_under_limit(256, 4096, 1024, 1024), ::testing::ExitedWithCode(0), "");
  // A low hard limit: fewer connections, leaving the reserve (128 + 2 workers + the probe lane's worker + 64
  // queued + 64 probes queued) free.
  EXPECT_EXIT(expect_capacity_under_limit(512, 512, 1024, 512 - 128 - 2 - 1 - 64 - 64), ::testing::ExitedWithCode(0), "");
}
