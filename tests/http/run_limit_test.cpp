// softtune/support/run_limit.h, as the service and the job runner use it: a CPU-time limit stops a loop
// within one poll interval of it, a cancel flag and a gone client stop it at the next poll, and a
// thread without a limit never stops.
#include "softtune/support/run_limit.h"

#include <gtest/gtest.h>

#include <atomic>
#include <optional>

using softtune::support::check_run_limit;
using softtune::support::kRunLimitPoll;
using softtune::support::RunStopped;
using softtune::support::ScopedRunLimit;
using softtune::support::thread_cpu_seconds;

// Named, not anonymous: the test sources are compiled together (unity builds), beside other helpers.
namespace run_limit_test {

// Spins, checking the limit, until it throws or `max_s` of CPU has passed; why it stopped and the CPU it took.
std::pair<std::optional<RunStopped::Why>, double> spin(double max_s) {
  const double start = thread_cpu_seconds();
  volatile double sink = 0.0;
  try {
    while (thread_cpu_seconds() - start < max_s) {
      for (int i = 0; i < 1000; ++i) sink = sink + i;
      check_run_limit();
    }
  } catch (const RunStopped& e) {
    return {e.why, thread_cpu_seconds() - start};
  }
  return {std::nullopt, thread_cpu_seconds() - start};
}


TEST(RunLimit, CpuTimeStopsTheWorkWithinOnePoll) {
  const ScopedRunLimit limit({0.1, nullptr, nullptr});
  const auto [why, spent] = spin(2.0);
  ASSERT_TRUE(why);
  EXPECT_EQ(*why, RunStopped::Why::budget);
  EXPECT_GE(spent, 0.1);
  EXPECT_LT(spent, 0.1 + 2 * std::chrono::duration<double>(kRunLimitPoll).count() + 0.02);
}

TEST(RunLimit, ACancelAndAGoneClientStopItAtTheNextPoll) {
  std::atomic<bool> cancelled{true};
  {
    const ScopedRunLimit limit({0.0, &cancelled, nullptr});
    const auto [why, spent] = spin(1.0);
    ASSERT_TRUE(why);
    EXPECT_EQ(*why, RunStopped::Why::cancelled);
    EXPECT_LT(spent, 0.05);
  }
  const ScopedRunLimit limit({0.0, nullptr, [] { return true; }});
  const auto [why, spent] = spin(1.0);
  ASSERT_TRUE(why);
  EXPECT_EQ(*why, RunStopped::Why::abandoned);
}

TEST(RunLimit, NoLimitNoStopAndTheOuterLimitComesBack) {
  EXPECT_FALSE(spin(0.05).first);
  std::atomic<bool> cancelled{false};
  const ScopedRunLimit outer({0.0, &cancelled, nullptr});
  { const ScopedRunLimit inner({0.0, nullptr, nullptr}); }
  cancelled = true;
  EXPECT_EQ(spin(0.5).first, RunStopped::Why::cancelled);
}

}  // namespace run_limit_test
