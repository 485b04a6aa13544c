#include "http/connection_gate.h"

#include <netinet/in.h>
#include <sys/epoll.h>
#include <sys/eventfd.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <unordered_map>
#include <vector>

#include "http/request_framing.h"

namespace softtune::http {
namespace {

using Clock = std::chrono::steady_clock;

// How often deadlines are checked: the resolution of every timeout the gate enforces.
constexpr std::chrono::milliseconds kSweepInterval{50};
// After a refusal the client may still be sending; closing at once would reset the connection and could
// destroy the answer before the client reads it. Discard what arrives for this long, at most this much.
constexpr std::chrono::milliseconds kDrainTime{500};
constexpr std::size_t kDrainBytes = 2u << 20;

// Descriptors kept free beyond the held connections: those being served or queued, the listening
// socket, epoll and eventfd, standard streams, Mesa's files when previews render.
constexpr std::size_t kDescriptorReserve = 128;

// Each held connection is a file descriptor. When the process may open fewer than it needs, raise the
// soft limit toward the hard one (Debian's shells start at 1024 soft); hold fewer connections if that
// is still short, so that accept() keeps working and eviction can make room.
std::size_t fit_to_descriptor_limit(std::size_t max_open, std::size_t reserve) {
  rlimit r{};
  if (::getrlimit(RLIMIT_NOFILE, &r) != 0) return max_open;
  const rlim_t wanted = static_cast<rlim_t>(max_open + reserve);
  if (r.rlim_cur != RLIM_INFINITY && r.rlim_cur < wanted) {
    rlimit raised = r;
    raised.rlim_cur = r.rlim_max == RLIM_INFINITY ? wanted : std::min<rlim_t>(wanted, r.rlim_max);
    if (::setrlimit(RLIMIT_NOFILE, &raised) == 0) r = raised;
  }
  if (r.rlim_cur == RLIM_INFINITY || r.rlim_cur >= wanted) return max_open;
  return r.rlim_cur > reserve + 16 ? static_cast<std::size_t>(r.rlim_cur) - reserve : 16;
}

struct Held {
  std::string received;
  Clock::time_point since;          ///< entered the gate
  Clock::time_point request_start;  ///< first byte of the request being read (meaningful once received is not empty)
  Clock::time_point deadline;
  std::size_t served = 0;
  bool draining = false;
  std::size_t discarded = 0;
  std::size_t wanted = 0;   ///< the whole request's bytes, once its head is complete (0 before)
  std::size_t counted = 0;  ///< bytes of `received` counted in State::buffered
};

struct Incoming {
  int sock;
  Held held;
  bool refused = false;  ///< answered at admission (client_limit): never takes another connection's place
};

void close_socket(int sock) {
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
}

}  // namespace

bool head_complete(std::string_view received) { return received.find("\r\n\r\n") != std::string_view::npos; }

std::string client_key(int sock) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (::getpeername(sock, reinterpret_cast<sockaddr*>(&addr), &len) != 0) return {};
  if (addr.ss_family == AF_INET) {
    const auto& a = reinterpret_cast<const sockaddr_in&>(addr);
    return std::string(reinterpret_cast<const char*>(&a.sin_addr), sizeof a.sin_addr);
  }
  if (addr.ss_family == AF_INET6) {
    const auto& a = reinterpret_cast<const sockaddr_in6&>(addr);
    const char* bytes = reinterpret_cast<const char*>(&a.sin6_addr);
    if (IN6_IS_ADDR_V4MAPPED(&a.sin6_addr)) return std::string(bytes + 12, 4);
    return std::string(bytes, sizeof a.sin6_addr);
  }
  return {};
}

struct ConnectionGate::State {
  GateOptions options;
  Serve serve;
  Refuse refuse;
  int epoll_fd = -1;
  int wake_fd = -1;

  std::mutex inbox_mutex;
  std::vector<Incoming> inbox;  ///< sockets to take into the poll loop (new, or back from a worker)
  bool stopping = false;

  // Connections open per client address (GateOptions::max_per_client), from admission to the final close,
  // wherever they are (held, queued, served). A socket is forgotten here before its descriptor is closed,
  // so a descriptor number reused by the next accept() is never counted twice.
  mutable std::mutex clients_mutex;
  std::unordered_map<int, std::string> client_of;          ///< admitted socket -> its client key
  std::unordered_map<std::string, std::size_t> open_from;  ///< client key -> connections open

  std::unordered_map<int, Held> held;  ///< touched by the poll thread only
  std::atomic<std::size_t> held_count{0};
  std::size_t buffered = 0;  ///< bytes received and held, summed over `held` (poll thread only)

  std::mutex ready_mutex;
  std::condition_variable ready_cv;
  std::deque<ReadyConnection> ready;  ///< complete requests waiting for a worker
  std::deque<ReadyConnection> lane;   ///< probes waiting for the reserved worker (or any idle one)
  std::condition_variable lane_cv;
  std::atomic<std::size_t> ready_count{0};
  std::atomic<std::size_t> idle_workers{0};  ///< workers blocked waiting for a connection
  bool workers_stop = false;

  std::thread poller;
  std::vector<std::thread> workers;
  std::thread lane_worker;

  void wake() const {
    const std::uint64_t one = 1;
    [[maybe_unused]] const ssize_t n = ::write(wake_fd, &one, sizeof one);
  }

  // From the accept thread: counts the connection against its client address, or, past that address's
  // limit, answers 503 at once and hands it to the poll loop only to drain.
  void admit(int sock) {
    std::string key = options.max_per_client > 0 ? client_key(sock) : std::string();
    if (!key.empty()) {
      const std::lock_guard lock(clients_mutex);
      std::size_t& open = open_from[key];
      if (open >= options.max_per_client) {
        Held h;
        answer_and_drain(sock, h, refuse(Refusal::client_limit, {}));
        take(sock, std::move(h), true);
        return;
      }
      ++open;
      client_of.emplace(sock, std::move(key));
    }
    take(sock, Held{});
  }

  // The final close of a connection: forget its client address first, then close the descriptor.
  void close_conn(int sock) {
    {
      const std::lock_guard lock(clients_mutex);
      const auto it = client_of.find(sock);
      if (it != client_of.end()) {
        const auto count = open_from.find(it->second);
        if (count != open_from.end() && --count->second == 0) open_from.erase(count);
        client_of.erase(it);
      }
    }
    close_socket(sock);
  }

  // From any thread: hand a socket to the poll loop, or close it when the gate has stopped.
  void take(int sock, Held h, bool refused = false) {
    {
      const std::lock_guard lock(inbox_mutex);
      if (!stopping) {
        inbox.push_back({sock, std::move(h), refused});
        sock = -1;
      }
    }
    if (sock >= 0) {
      close_conn(sock);
      return;
    }
    wake();
  }

  // ---- poll thread ----

  void account(Held& h) {
    buffered += h.received.size() - h.counted;
    h.counted = h.received.size();
  }

  void forget(std::unordered_map<int, Held>::iterator it) {
    buffered -= it->second.counted;
    ::epoll_ctl(epoll_fd, EPOLL_CTL_DEL, it->first, nullptr);
    held.erase(it);
    held_count.store(held.size(), std::memory_order_relaxed);
  }

  void drop(std::unordered_map<int, Held>::iterator it) {
    const int sock = it->first;
    forget(it);
    close_conn(sock);
  }

  // Send an answer, half-close, and keep the socket only to discard what the client still sends.
  static void answer_and_drain(int sock, Held& h, const std::string& response) {
    ::send(sock, response.data(), response.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    ::shutdown(sock, SHUT_WR);
    h.draining = true;
    h.discarded = 0;
    h.deadline = Clock::now() + kDrainTime;
  }

  // Which held connection gives way to a new one: a draining one if any, else the one that has waited
  // longest. Not the idle ones first: a connection just accepted has not sent its head yet, and must
  // not be the first victim of clients that send theirs slowly.
  std::unordered_map<int, Held>::iterator least_valuable() {
    auto worst = held.begin();
    for (auto it = held.begin(); it != held.end(); ++it) {
      const Held& h = it->second;
      const Held& w = worst->second;
      if (h.draining != w.draining ? h.draining : h.since < w.since) worst = it;
    }
    return worst;
  }

  void insert(Incoming in) {
    if (held.size() >= options.max_open && in.refused) {
      close_conn(in.sock);
      return;
    }
    if (held.size() >= options.max_open && !held.empty()) drop(least_valuable());
    Held& h = in.held;
    h.since = Clock::now();
    if (!h.draining) {
      h.deadline = h.received.empty() ? h.since + options.keep_alive_timeout
                                      : h.request_start + options.request_read_timeout;
    } else {
      h.deadline = h.since + kDrainTime;
    }
    epoll_event ev{};
    ev.events = EPOLLIN | EPOLLRDHUP;
    ev.data.fd = in.sock;
    if (::epoll_ctl(epoll_fd, EPOLL_CTL_ADD, in.sock, &ev) != 0) {
      close_conn(in.sock);
      return;
    }
    const int in_sock = in.sock;
    const auto [it, inserted] = held.insert_or_assign(in.sock, std::move(in.held));
    held_count.store(held.size(), std::memory_order_relaxed);
    // A worker that gave way to others may hand back a connection whose next request it already read.
    if (it->second.draining) return;
    account(it->second);
    // Read at once what has already arrived: under a flood of new connections a whole batch is inserted
    // before epoll reports any of them readable, and a client whose head came in one packet (a health
    // probe) must not wait in the gate, where later arrivals of the batch could evict it.
    if (progress(it)) on_readable(in_sock);
  }

  // Hands the connection to a worker once its request is complete (or its head too large to wait for);
  // until then sets the body's deadline when the head completes. True while the request still arrives.
  bool progress(std::unordered_map<int, Held>::iterator it) {
    Held& h = it->second;
    if (h.wanted == 0) {
      const std::optional<std::size_t> size = request_size(h.received, options.max_body_bytes);
      if (!size) {
        if (h.received.size() <= options.max_head_bytes) return true;
        hand_over(it);
        return false;
      }
      h.wanted = *size;
      const std::size_t body = *size - *head_size(h.received);
      if (body > 0) {
        const auto body_time = options.body_grace + std::chrono::milliseconds(body * 1000 / options.min_body_rate);
        h.deadline = std::min(h.deadline, Clock::now() + body_time);
      }
    }
    if (h.received.size() < h.wanted) return true;
    hand_over(it);
    return false;
  }

  // Queues the request for a worker (a probe for the reserved lane), or answers 503 when its queue is full.
  void hand_over(std::unordered_map<int, Held>::iterator it) {
    const int sock = it->first;
    Held& h = it->second;
    const bool probe = is_lane_request(h.received);
    {
      const std::lock_guard lock(ready_mutex);
      std::deque<ReadyConnection>& queue = probe ? lane : ready;
      if (queue.size() < (probe ? options.max_lane : options.max_ready)) {
        queue.push_back({sock, std::move(h.received), h.request_start, h.served, probe});
        ready_count.store(ready.size(), std::memory_order_relaxed);
        forget(it);
        if (probe) lane_cv.notify_one();
        ready_cv.notify_one();
        return;
      }
    }
    answer_and_drain(sock, h, refuse(Refusal::busy, h.received));
  }

  // Past max_buffered_bytes, the connections that have waited longest make room.
  void make_room() {
    while (buffered > options.max_buffered_bytes && !held.empty()) drop(least_valuable());
  }

  void on_readable(int sock) {
    const auto it = held.find(sock);
    if (it == held.end()) return;
    Held& h = it->second;
    std::array<char, 4096> buf;
    const ssize_t n = ::recv(sock, buf.data(), buf.size(), MSG_DONTWAIT);
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) return;
    if (n <= 0) {
      drop(it);
      return;
    }
    if (h.draining) {
      h.discarded += static_cast<std::size_t>(n);
      if (h.discarded > kDrainBytes) drop(it);
      return;
    }
    if (h.received.empty()) {
      h.request_start = Clock::now();
      h.deadline = h.request_start + options.request_read_timeout;
    }
    h.received.append(buf.data(), static_cast<std::size_t>(n));
    account(h);
    if (buffered > options.max_buffered_bytes) {
      make_room();
      if (held.find(sock) == held.end()) return;
    }
    progress(it);
  }

  void sweep() {
    const Clock::time_point now = Clock::now();
    for (auto it = held.begin(); it != held.end();) {
      const auto current = it++;
      Held& h = current->second;
      if (now < h.deadline) continue;
      if (h.draining || h.received.empty()) {
        drop(current);
      } else {
        answer_and_drain(current->first, h, refuse(Refusal::timeout, h.received));
      }
    }
  }

  // Returns false once the gate is stopping.
  bool take_inbox() {
    std::vector<Incoming> taken;
    bool stop = false;
    {
      const std::lock_guard lock(inbox_mutex);
      taken.swap(inbox);
      stop = stopping;
    }
    for (Incoming& in : taken) {
      if (stop) {
        close_conn(in.sock);
      } else {
        insert(std::move(in));
      }
    }
    return !stop;
  }

  void poll_loop() {
    std::array<epoll_event, 64> events;
    Clock::time_point next_sweep = Clock::now() + kSweepInterval;
    for (;;) {
      const int n = ::epoll_wait(epoll_fd, events.data(), static_cast<int>(events.size()),
                                 static_cast<int>(kSweepInterval.count()));
      for (int i = 0; i < n; ++i) {
        if (events[i].data.fd == wake_fd) {
          std::uint64_t count;
          [[maybe_unused]] const ssize_t r = ::read(wake_fd, &count, sizeof count);
        } else {
          on_readable(events[i].data.fd);
        }
      }
      if (!take_inbox()) break;
      if (Clock::now() >= next_sweep) {
        sweep();
        next_sweep = Clock::now() + kSweepInterval;
      }
    }
    for (auto& [sock, h] : held) close_conn(sock);
    held.clear();
    held_count.store(0);
  }

  // ---- worker threads ----

  // A worker takes a waiting probe first, then the oldest request.
  void work() {
    for (;;) {
      ReadyConnection c;
      {
        std::unique_lock lock(ready_mutex);
        idle_workers.fetch_add(1, std::memory_order_relaxed);
        ready_cv.wait(lock, [this] { return workers_stop || !ready.empty() || !lane.empty(); });
        idle_workers.fetch_sub(1, std::memory_order_relaxed);
        std::deque<ReadyConnection>& queue = lane.empty() ? ready : lane;
        if (queue.empty()) return;
        c = std::move(queue.front());
        queue.pop_front();
        ready_count.store(ready.size(), std::memory_order_relaxed);
      }
      serve_and_return(std::move(c));
    }
  }

  // The reserved lane's worker serves probes only: however long the other requests run, one thread is free
  // for health and metrics.
  void work_lane() {
    for (;;) {
      ReadyConnection c;
      {
        std::unique_lock lock(ready_mutex);
        lane_cv.wait(lock, [this] { return workers_stop || !lane.empty(); });
        if (lane.empty()) return;
        c = std::move(lane.front());
        lane.pop_front();
      }
      serve_and_return(std::move(c));
    }
  }

  void serve_and_return(ReadyConnection c) {
    AfterServe after = AfterServe::close;
    try {
      after = serve(c);
    } catch (...) {
      after = AfterServe::close;
    }
    if (after == AfterServe::close) {
      close_conn(c.sock);
      return;
    }
    Held h;
    h.received = std::move(c.received);
    h.request_start = c.request_start;
    h.served = c.served;
    if (after == AfterServe::drain_and_close) {
      ::shutdown(c.sock, SHUT_WR);
      h.draining = true;
    }
    take(c.sock, std::move(h));
  }
};

ConnectionGate::ConnectionGate(GateOptions options, Serve serve, Refuse refuse) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.options = options;
  s.options.max_open = fit_to_descriptor_limit(
      options.max_open,
      kDescriptorReserve + static_cast<std::size_t>(options.threads) + 1 + options.max_ready + options.max_lane);
  s.serve = std::move(serve);
  s.refuse = std::move(refuse);
  s.epoll_fd = ::epoll_create1(EPOLL_CLOEXEC);
  s.wake_fd = ::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
  if (s.epoll_fd < 0 || s.wake_fd < 0) throw std::runtime_error("cannot create the connection gate's epoll or eventfd");
  epoll_event ev{};
  ev.events = EPOLLIN;
  ev.data.fd = s.wake_fd;
  ::epoll_ctl(s.epoll_fd, EPOLL_CTL_ADD, s.wake_fd, &ev);
  s.poller = std::thread([&s] { s.poll_loop(); });
  for (int i = 0; i < options.threads; ++i) s.workers.emplace_back([&s] { s.work(); });
  s.lane_worker = std::thread([&s] { s.work_lane(); });
}

ConnectionGate::~ConnectionGate() { shutdown(); }

void ConnectionGate::admit(int sock) { state_->admit(sock); }

void ConnectionGate::shutdown() {
  State& s = *state_;
  {
    const std::lock_guard lock(s.inbox_mutex);
    if (s.stopping) return;
    s.stopping = true;
  }
  s.wake();
  s.poller.join();
  {
    const std::lock_guard lock(s.ready_mutex);
    s.workers_stop = true;
  }
  s.ready_cv.notify_all();
  s.lane_cv.notify_all();
  for (std::thread& t : s.workers) t.join();
  s.lane_worker.join();
  ::close(s.epoll_fd);
  ::close(s.wake_fd);
}

bool ConnectionGate::requests_waiting() const {
  return state_->ready_count.load(std::memory_order_relaxed) > state_->idle_workers.load(std::memory_order_relaxed);
}

std::size_t ConnectionGate::capacity() const { return state_->options.max_open; }

std::size_t ConnectionGate::held() const { return state_->held_count.load(std::memory_order_relaxed); }

std::size_t ConnectionGate::open_from(const std::string& client_key) const {
  const std::lock_guard lock(state_->clients_mutex);
  const auto it = state_->open_from.find(client_key);
  return it == state_->open_from.end() ? 0 : it->second;
}

}  // namespace softtune::http
