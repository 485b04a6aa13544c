// The long-lived node worker (engines/node_worker/node_worker.cpp) with the real node and the real
// scene_worker.mjs: started once and reused, restarted after a crash, a clear error for a missing engine
// module, a missing node and a worker that never answers, and round trips from several threads at once.
#include "node_worker.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>
#include <vector>

namespace softtune::node_worker {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A scratch folder holding a copy of scene_worker.mjs with no engine module beside it.
fs::path worker_test_lonely_script() {
  const fs::path dir = fs::temp_directory_path() / ("node_worker_test_" + std::to_string(::getpid())) / "engines/node_worker";
  fs::create_directories(dir);
  fs::copy_file(scene_worker_script(), dir / "scene_worker.mjs", fs::copy_options::overwrite_existing);
  return dir / "scene_worker.mjs";
}

WorkerOptions worker_test_options(std::string node, fs::path script, std::chrono::milliseconds timeout = std::chrono::milliseconds(30000)) {
  WorkerOptions o;
  o.node = std::move(node);
  o.script = std::move(script);
  o.timeout = timeout;
  return o;
}

TEST(NodeWorker, StartsOnceAndIsReusedForManyCalls) {
  NodeWorker worker;
  EXPECT_EQ(worker.generation(), 0);  // nothing runs before the first call
  std::set<int> pids;
  for (int i = 0; i < 20; ++i) {
    const json answer = worker.call({{"op", "ping"}});
    ASSERT_TRUE(answer.value("ok", false)) << answer.dump();
    pids.insert(answer["pid"].get<int>());
  }
  EXPECT_EQ(pids.size(), 1u);
  EXPECT_EQ(*pids.begin(), worker.pid());
  EXPECT_EQ(worker.generation(), 1);
}

TEST(NodeWorker, PerFrameRoundTripIsMeasured) {
  NodeWorker worker;
  worker.call({{"op", "ping"}});  // the start is not part of the round trip
  constexpr int kCalls = 500;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < kCalls; ++i) worker.call({{"op", "ping"}});
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / kCalls;
  std::printf("node worker round trip: %.1f us per call (%d pings)\n", us, kCalls);
  EXPECT_GT(us, 0.0);
}

TEST(NodeWorker, ACrashedWorkerIsStartedAgain) {
  NodeWorker worker;
  const int first = worker.call({{"op", "ping"}})["pid"].get<int>();
  const int generation = worker.generation();
  ASSERT_EQ(::kill(first, SIGKILL), 0);
  // The next free call finds the worker dead, starts a new one and answers.
  const json answer = worker.call({{"op", "ping"}});
  ASSERT_TRUE(answer.value("ok", false)) << answer.dump();
  EXPECT_NE(answer["pid"].get<int>(), first);
  EXPECT_EQ(worker.generation(), generation + 1);
  // A call bound to the dead worker's world says the world is lost instead of asking the new worker.
  try {
    worker.call({{"op", "step"}, {"world", 1}, {"frame", 0}}, generation);
    FAIL() << "a call bound to the old worker answered";
  } catch (const WorkerError& e) {
    EXPECT_NE(std::string(e.what()).find("world is lost"), std::string::npos) << e.what();
  }
}

TEST(NodeWorker, AMissingEngineModuleAnswersAClearError) {
  NodeWorker worker(worker_test_options("", worker_test_lonely_script()));
  const json answer = worker.call({{"op", "build"}, {"engine", "rapier"}, {"bodies", json::array()}, {"joints", json::array()}});
  EXPECT_FALSE(answer.value("ok", true));
  EXPECT_EQ(answer.value("field", ""), "engine");
  const std::string message = answer.value("message", "");
  EXPECT_NE(message.find("rapier"), std::string::npos) << message;
  EXPECT_NE(message.find("cannot be loaded"), std::string::npos) << message;
  const json unknown = worker.call({{"op", "build"}, {"engine", "havok"}});
  EXPECT_EQ(unknown.value("field", ""), "engine");
  EXPECT_NE(unknown.value("message", "").find("havok"), std::string::npos) << unknown.dump();
  EXPECT_TRUE(worker.call({{"op", "ping"}}).value("ok", false));  // the worker lives on
}

TEST(NodeWorker, AMissingNodeIsAClearError) {
  NodeWorker worker(worker_test_options("/nonexistent/node", ""));
  try {
    worker.call({{"op", "ping"}});
    FAIL() << "no error without node";
  } catch (const WorkerError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot start /nonexistent/node"), std::string::npos) << e.what();
  }
  NodeWorker no_script(worker_test_options("", "/nonexistent/scene_worker.mjs"));
  EXPECT_THROW(no_script.call({{"op", "ping"}}), WorkerError);
}

TEST(NodeWorker, AWorkerThatNeverAnswersTimesOut) {
  const fs::path silent = fs::temp_directory_path() / ("node_worker_silent_" + std::to_string(::getpid()) + ".mjs");
  std::ofstream(silent) << "process.stdin.on('data', () => {});\n";
  NodeWorker worker(worker_test_options("", silent, std::chrono::milliseconds(300)));
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_THROW(worker.call({{"op", "ping"}}), WorkerError);
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
  EXPECT_EQ(worker.pid(), -1);  // the silent worker was stopped
  fs::remove(silent);
}

TEST(NodeWorker, ConcurrentCallsFromThreadsShareOneProcess) {
  NodeWorker worker;
  constexpr int kThreads = 4, kCalls = 25;
  std::vector<std::set<int>> seen(kThreads);
  std::vector<int> failures(kThreads, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&worker, &seen, &failures, t] {
      for (int i = 0; i < kCalls; ++i) {
        const json answer = worker.call({{"op", "ping"}});
        if (!answer.value("ok", false)) ++failures[t];
        seen[t].insert(answer.value("pid", -1));
      }
    });
  }
  for (std::thread& th : threads) th.join();
  std::set<int> pids;
  for (int t = 0; t < kThreads; ++t) {
    EXPECT_EQ(failures[t], 0);
    pids.insert(seen[t].begin(), seen[t].end());
  }
  EXPECT_EQ(pids.size(), 1u);
  EXPECT_EQ(worker.generation(), 1);
}

}  // namespace
}  // namespace softtune::node_worker
