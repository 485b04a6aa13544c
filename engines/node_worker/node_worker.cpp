#include "node_worker.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

extern char** environ;

namespace softtune::node_worker {
namespace fs = std::filesystem;
namespace {

constexpr const char* kScript = "engines/node_worker/scene_worker.mjs";

std::string executable_dir() {
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) return {};
  std::string dir(exe, static_cast<std::size_t>(n));
  return dir.substr(0, dir.rfind('/') + 1);
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status));
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "stopped";
}

}  // namespace

fs::path scene_worker_script() {
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("SOFTTUNE_NODE_WORKER"); env && *env) candidates.emplace_back(env);
  if (const std::string dir = executable_dir(); !dir.empty()) {
    candidates.push_back(fs::path(dir) / "../share/softtune" / kScript);
  }
  candidates.push_back(fs::path(SOFTTUNE_SOURCE_DIR) / kScript);
  std::string tried;
  for (const fs::path& p : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return fs::weakly_canonical(p, ec);
    tried += (tried.empty() ? "" : ", ") + p.string();
  }
  throw WorkerError("node worker: scene_worker.mjs is not installed (looked for " + tried + ")");
}

NodeWorker::NodeWorker(WorkerOptions options) : options_(std::move(options)) {}

NodeWorker::~NodeWorker() {
  std::lock_guard lock(mutex_);
  stop(2000);
}

int NodeWorker::generation() const {
  std::lock_guard lock(mutex_);
  return generation_;
}

pid_t NodeWorker::pid() const {
  std::lock_guard lock(mutex_);
  return pid_;
}

void NodeWorker::start() {
  const fs::path script = options_.script.empty() ? scene_worker_script() : options_.script;
  if (std::error_code ec; !fs::is_regular_file(script, ec)) {
    throw WorkerError("node worker: the script " + script.string() + " does not exist");
  }
  std::string node = options_.node;
  if (node.empty()) {
    const char* env = std::getenv("SOFTTUNE_NODE");
    node = env && *env ? env : "node";
  }
  // One socket pair is the worker's stdin and stdout: send() with MSG_NOSIGNAL never raises SIGPIPE in the
  // server when the worker has died.
  int sv[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
    throw WorkerError(std::string("node worker: socketpair: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, sv[1], 0);
  posix_spawn_file_actions_adddup2(&actions, sv[1], 1);
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);  // stderr stays: node's and the engines' messages
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);
  const std::string script_arg = script.string();
  const char* argv[] = {node.c_str(), script_arg.c_str(), nullptr};
  pid_t pid = -1;
  const int spawned = posix_spawnp(&pid, node.c_str(), &actions, &attributes, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(sv[1]);
  if (spawned != 0) {
    ::close(sv[0]);
    throw WorkerError("node worker: cannot start " + node + " (" + std::strerror(spawned) +
                      "): the Jolt and Rapier scenes need node on PATH or $SOFTTUNE_NODE");
  }
  pid_ = pid;
  socket_ = sv[0];
  buffer_.clear();
  ++generation_;
}

void NodeWorker::stop(int grace_ms) {
  if (socket_ >= 0) ::close(socket_);  // end of input: the worker's read loop ends and node exits
  socket_ = -1;
  if (pid_ <= 0) return;
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(grace_ms);
  for (;;) {
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_ || (r < 0 && errno != EINTR)) break;
    if (r == 0 && std::chrono::steady_clock::now() >= deadline) {
      kill(pid_, SIGKILL);
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  pid_ = -1;
}

nlohmann::json NodeWorker::round_trip(const std::string& line) {
  for (std::size_t sent = 0; sent < line.size();) {
    const ssize_t n = ::send(socket_, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw WorkerError(std::string("node worker: the worker is gone (send: ") + std::strerror(errno) + ")");
    sent += static_cast<std::size_t>(n);
  }
  const auto deadline = std::chrono::steady_clock::now() + options_.timeout;
  std::size_t end;
  while ((end = buffer_.find('\n')) == std::string::npos) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      stop(0);
      timed_out_ = true;
      throw WorkerError("node worker: no answer within " + std::to_string(options_.timeout.count()) +
                        " ms (the worker was stopped)");
    }
    pollfd p{socket_, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char chunk[65536];
    const ssize_t n = ::recv(socket_, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw WorkerError("node worker: the worker is gone (end of its output)");
    buffer_.append(chunk, static_cast<std::size_t>(n));
  }
  const std::string answer = buffer_.substr(0, end);
  buffer_.erase(0, end + 1);
  try {
    return nlohmann::json::parse(answer);
  } catch (const nlohmann::json::exception& e) {
    stop(0);
    throw WorkerError(std::string("node worker: a broken answer line (") + e.what() + ")");
  }
}

nlohmann::json NodeWorker::call(const nlohmann::json& request, int generation) {
  const std::string line = request.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  std::lock_guard lock(mutex_);
  for (int attempt = 0;; ++attempt) {
    if (socket_ < 0) {
      stop(0);  // reap a worker that died
      if (generation != 0) throw WorkerError("node worker: the worker that held this world stopped; the world is lost");
      start();
    }
    if (generation != 0 && generation != generation_) {
      throw WorkerError("node worker: the worker that held this world stopped; the world is lost");
    }
    timed_out_ = false;
    try {
      return round_trip(line);
    } catch (const WorkerError& e) {
      // A dead worker: reap it (and say how it ended); a free request gets one more try on a new worker.
      int status = 0;
      const bool reaped = pid_ > 0 && waitpid(pid_, &status, WNOHANG) == pid_;
      if (reaped) pid_ = -1;
      stop(0);
      if (generation != 0 || attempt > 0 || timed_out_) {
        throw WorkerError(std::string(e.what()) + (reaped ? "; it " + describe(status) : std::string()));
      }
    }
  }
}

NodeWorker& shared_worker() {
  static NodeWorker worker;
  return worker;
}

}  // namespace softtune::node_worker
