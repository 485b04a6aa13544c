#include "raster_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "raster_protocol.h"

extern char** environ;

namespace softtune::render {
namespace {

std::atomic<int> g_processes_started{0};
std::atomic<int> g_contexts_created{0};

// Next to the running executable first (a copied build/ keeps working), then where this build put it.
std::string raster_executable() {
  std::vector<std::string> candidates;
  char exe[PATH_MAX];
  if (const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1); n > 0) {
    std::string dir(exe, static_cast<std::size_t>(n));
    dir.resize(dir.rfind('/') + 1);
    candidates.push_back(dir + "softtune-raster");
  }
  if (candidates.empty() || candidates.front() != SOFTTUNE_RASTER_PATH) candidates.emplace_back(SOFTTUNE_RASTER_PATH);
  std::string tried;
  for (const std::string& path : candidates) {
    if (access(path.c_str(), X_OK) == 0) return path;
    tried += (tried.empty() ? "" : ", ") + path;
  }
  throw std::runtime_error("render: the raster process softtune-raster is not installed (looked for " + tried + ")");
}

std::string describe(int status) {
  if (WIFSIGNALED(status)) return "was killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  return "stopped";
}

}  // namespace

RasterProcess::RasterProcess(const RasterProcessOptions& options) : options_(options) {
  const std::string path = raster_executable();
  int sv[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
    throw std::runtime_error(std::string("render: socketpair: ") + std::strerror(errno));
  }
  // The child's end must sit above fd 3, so that dup2 onto 3 always clears close-on-exec.
  int child_end = sv[1];
  if (child_end <= raster::kSocketFd) {
    child_end = fcntl(sv[1], F_DUPFD_CLOEXEC, raster::kSocketFd + 1);
    ::close(sv[1]);
  }
  if (child_end < 0) {
    ::close(sv[0]);
    throw std::runtime_error(std::string("render: fcntl: ") + std::strerror(errno));
  }

  // The child keeps stderr (Mesa's warnings, sanitizer reports) and nothing else of ours: no client
  // sockets, no listening socket, no stdout (the CLI prints its answer there).
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, child_end, raster::kSocketFd);
  posix_spawn_file_actions_addclosefrom_np(&actions, raster::kSocketFd + 1);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);  // the spawning thread may block signals; the child must not
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK);

  const std::string msaa = std::to_string(options.msaa_samples), threads = std::to_string(options.llvmpipe_threads);
  const char* argv[] = {path.c_str(), "--msaa", msaa.c_str(), "--llvmpipe-threads", threads.c_str(), nullptr};
  const int spawned = posix_spawn(&pid_, path.c_str(), &actions, &attributes, const_cast<char* const*>(argv), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(child_end);
  if (spawned != 0) {
    ::close(sv[0]);
    pid_ = -1;
    throw std::runtime_error("render: cannot start " + path + ": " + std::strerror(spawned));
  }
  socket_ = sv[0];
  g_processes_started.fetch_add(1, std::memory_order_relaxed);
}

RasterProcess::~RasterProcess() {
  if (alive()) close_and_wait();
}

double RasterProcess::cpu_seconds() const {
  if (pid_ <= 0) return 0.0;
  std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
  std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Fields after the command name, which is in parentheses and may hold spaces: state is field 3,
  // utime and stime fields 14 and 15 (proc(5)).
  const std::size_t close = stat.rfind(')');
  if (close == std::string::npos) return 0.0;
  std::istringstream fields(stat.substr(close + 1));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && fields >> field; ++i) {
    if (i == 14) utime = std::stoull(field);
    if (i == 15) stime = std::stoull(field);
  }
  return static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

int RasterProcess::close_and_wait() {
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  return reap(2000);
}

int RasterProcess::reap(int grace_ms) {
  if (pid_ <= 0) return 0;
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(grace_ms);
  for (;;) {
    const pid_t r = waitpid(pid_, &status, WNOHANG);
    if (r == pid_) break;
    if (r < 0 && errno != EINTR) {  // ECHILD: reaped elsewhere (SIGCHLD ignored); nothing to report
      status = 0;
      break;
    }
    if (r == 0 && std::chrono::steady_clock::now() >= deadline) {
      kill(pid_, SIGKILL);
      while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  pid_ = -1;
  return status;
}

void RasterProcess::fail(const std::string& what) {
  if (socket_ >= 0) ::close(socket_);
  socket_ = -1;
  if (pid_ > 0) kill(pid_, SIGKILL);
  reap(0);
  throw std::runtime_error("render: the raster process " + what);
}

void RasterProcess::rasterize(std::span<const Vertex> vertices, ImageSize size, std::span<std::uint8_t> rgba) {
  using raster::Io;
  if (!alive()) throw std::runtime_error("render: the raster process is not running");
  if (!is_rgba_of(size, rgba.size()) || static_cast<std::uint32_t>(size.width) > raster::kMaxSide ||
      static_cast<std::uint32_t>(size.height) > raster::kMaxSide || vertices.size() > raster::kMaxVertices) {
    throw std::invalid_argument("render: the frame does not fit the raster process (size, vertices or buffer)");
  }
  raster::RasterRequest request;
  request.width = static_cast<std::uint32_t>(size.width);
  request.height = static_cast<std::uint32_t>(size.height);
  request.vertex_count = vertices.size();
  Io io = raster::send_all(socket_, &request, sizeof request);
  if (io == Io::ok) io = raster::send_all(socket_, vertices.data(), vertices.size_bytes());
  raster::RasterReply reply;
  if (io == Io::ok) io = raster::receive_exact(socket_, &reply, sizeof reply, options_.frame_timeout_ms);
  if (io == Io::eof) {
    ::close(socket_);
    socket_ = -1;
    throw std::runtime_error("render: the raster process " + describe(reap(2000)) + " during a frame");
  }
  if (io == Io::timeout) fail("took longer than " + std::to_string(options_.frame_timeout_ms) + " ms for a frame");
  if (io != Io::ok) fail(std::string("socket failed: ") + std::strerror(errno));
  if (reply.magic != raster::kReplyMagic || reply.message_bytes > raster::kMaxMessageBytes) fail("broke the protocol");
  if (!reply.ok) {
    std::string message(reply.message_bytes, '\0');
    if (raster::receive_exact(socket_, message.data(), message.size(), options_.frame_timeout_ms) != Io::ok) {
      fail("broke the protocol");
    }
    throw std::runtime_error(message);
  }
  if (raster::receive_exact(socket_, rgba.data(), rgba.size(), options_.frame_timeout_ms) != Io::ok) {
    fail("stopped in the middle of a frame");
  }
  if (reply.context_created) g_contexts_created.fetch_add(1, std::memory_order_relaxed);
}

int raster_processes_started() { return g_processes_started.load(std::memory_order_relaxed); }

int gl_contexts_created() { return g_contexts_created.load(std::memory_order_relaxed); }

}  // namespace softtune::render
