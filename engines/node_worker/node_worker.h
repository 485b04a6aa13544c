#pragma once
// The long-lived node worker: one `node engines/node_worker/scene_worker.mjs` process, started on first use
// and reused for every scene run in a JavaScript engine (Jolt, Rapier as WebAssembly), never one node start
// per request. Requests and answers are newline-delimited JSON (the protocol: scene_worker.mjs's header;
// docs/scene-backends.md, "The node worker").
//
// Thread safe: the HTTP server runs requests on several threads; one mutex per worker serialises the round
// trips (each is one request line and one answer line), so the threads' worlds interleave by id. A worker that
// died (crashed, killed) is started again on the next call; a call that finds it dead is retried once on the
// new worker when it is not bound to a world of the old one. Every read waits at most `timeout`: a worker that
// does not answer is killed and the call fails, so nothing hangs.

#include <chrono>
#include <filesystem>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <sys/types.h>

namespace softtune::node_worker {

/// The worker could not answer: node or the script missing, the process died twice, a timeout, a broken line.
struct WorkerError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WorkerOptions {
  std::string node;                 ///< the node program; empty: $SOFTTUNE_NODE, else `node` on PATH
  std::filesystem::path script;     ///< empty: scene_worker_script()
  std::chrono::milliseconds timeout{30000};  ///< longest wait for one answer
};

/// scene_worker.mjs: $SOFTTUNE_NODE_WORKER when set; else beside the running program's installed share dir
/// (<bin>/../share/softtune/engines/node_worker/, where the package installs it), else in this source tree.
/// Throws WorkerError naming the places looked at.
std::filesystem::path scene_worker_script();

class NodeWorker {
 public:
  explicit NodeWorker(WorkerOptions options = {});
  NodeWorker(const NodeWorker&) = delete;
  NodeWorker& operator=(const NodeWorker&) = delete;
  ~NodeWorker();  ///< closes the worker's input (it exits on end of input), kills it after a grace period

  /// One round trip. `generation`: the worker generation the request is bound to (a world's), or 0 for a
  /// request that may run on any worker (build, ping): such a request is retried once on a restarted worker.
  nlohmann::json call(const nlohmann::json& request, int generation = 0);

  /// The current worker's generation: 1 for the first process, +1 per restart; 0 before the first start.
  int generation() const;
  /// The current worker's process id (-1 when none runs).
  pid_t pid() const;

 private:
  void start();            // with mutex_ held
  void stop(int grace_ms); // with mutex_ held
  nlohmann::json round_trip(const std::string& line);  // with mutex_ held; throws WorkerError

  WorkerOptions options_;
  mutable std::mutex mutex_;
  pid_t pid_ = -1;
  int socket_ = -1;
  int generation_ = 0;
  bool timed_out_ = false; // the last round trip timed out (never retried: nothing waits twice)
  std::string buffer_;     // bytes read past the last answer line
};

/// The process-wide worker every scene backend over node shares (started on its first call).
NodeWorker& shared_worker();

}  // namespace softtune::node_worker
