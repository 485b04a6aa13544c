// `softtune serve`: the HTTP API and the page (docs/api.md, "HTTP API"). Runs until SIGINT or SIGTERM,
// then finishes the requests in flight and exits 0.
#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include "cli/cli_io.h"
#include "app/preset_store.h"
#include "codec/problem.h"
#include "http/http_transport.h"
#include "http/limits.h"
#include "http/routes.h"

namespace softtune::cli {
namespace {

constexpr const char* kServeHelp = R"(softtune serve: the REST API under /api/v1/ and the page from web/.

  --host H       address to listen on (default 127.0.0.1)
  --port P       TCP port (default 8080; 0 picks a free one)
  --threads N    worker threads, one per request being served (default 8, at most 256)
  --max-client-connections N  connections one client address may have open at once (default 128,
                 1 to 1024); the next one is answered 503. Raise it when many users share one address (NAT)
  --web DIR      folder of the static page (default web/, relative to the working directory)
  --cors-origin O  answer cross-origin requests from origin O ("https://tools.example:8443"; repeatable;
                 "*" for any): CORS headers on every answer, preflights answered (default: off)
  --presets DIR  presets directory of /api/v1/simulate and /api/v1/presets (default: $SOFTTUNE_PRESETS,
                 else presets/, relative to the working directory)

Prints the URL, then one line per request on stderr: method, path, status, microseconds.
SIGINT or SIGTERM stops it after the requests in flight.
)";

int integer_flag(const Flags& f, const std::string& name, int fallback, int lo, int hi) {
  if (!f.has(name)) return fallback;
  const double v = flag_number(f, name);
  if (v != static_cast<int>(v) || v < lo || v > hi) {
    throw codec::invalid_field("--" + name, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return static_cast<int>(v);
}

// Every value of a flag given more than once (Flags keeps the last): --cors-origin A --cors-origin=B.
std::vector<std::string> repeated_flag(const Args& args, const std::string& name) {
  std::vector<std::string> out;
  const std::string flag = "--" + name;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == flag && i + 1 < args.size()) out.push_back(args[++i]);
    else if (args[i].rfind(flag + "=", 0) == 0) out.push_back(args[i].substr(flag.size() + 1));
  }
  for (const std::string& origin : out) {
    if (origin != "*" && origin.find("://") == std::string::npos) {
      throw codec::invalid_field(flag, "must be an origin (scheme://host[:port]) or *, got \"" + origin + "\"");
    }
  }
  return out;
}

void log_line(std::string_view line) {
  std::string out(line);
  out += '\n';
  std::fwrite(out.data(), 1, out.size(), stderr);  // one write per line: lines from workers do not interleave
}

}  // namespace

int run_serve(const Args& args) {
  return guarded([&] {
    const Flags flags = parse_flags(args, {"host", "port", "threads", "max-client-connections", "web", "presets", "cors-origin"}, {"help"});
    if (flags.has("help")) {
      std::cout << kServeHelp;
      return kExitOk;
    }
    http::TransportOptions options;
    options.host = flags.get("host").value_or("127.0.0.1");
    options.port = integer_flag(flags, "port", 8080, 0, 65535);
    options.threads = integer_flag(flags, "threads", http::limits::kDefaultThreads, 1, http::limits::kMaxThreads);
    options.max_client_connections = static_cast<std::size_t>(
        integer_flag(flags, "max-client-connections", static_cast<int>(http::limits::kMaxConnectionsPerClient), 1,
                     static_cast<int>(http::limits::kMaxOpenConnections)));
    options.log = log_line;
    http::ServiceConfig config;
    config.web_root = flags.get("web").value_or("web");
    if (!std::filesystem::is_directory(config.web_root)) {
      std::cerr << "softtune: web folder \"" << config.web_root.string() << "\" not found; the page will answer 404\n";
    }
    config.presets_dir = app::resolve_presets_dir(flags.get("presets"));
    config.cors.origins = repeated_flag(args, "cors-origin");
    if (!std::filesystem::is_directory(config.presets_dir)) {
      std::cerr << "softtune: presets folder \"" << config.presets_dir << "\" not found; /api/v1/presets will answer 404\n";
    }

    // SIGINT/SIGTERM are blocked in every thread and taken by one waiter, which stops the server
    // outside of signal context (stop() is not async-signal-safe). Threads inherit the mask.
    sigset_t stop_signals;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

    http::Service service(config, http::service_routes());
    http::HttpServer server(service, options);
    int port = 0;
    try {
      port = server.bind();
    } catch (const std::exception& e) {
      std::cerr << "softtune: " << e.what() << '\n';
      return kExitFailed;
    }
    std::atomic<bool> finished{false};
    std::thread waiter([&] {
      int signal = 0;
      sigwait(&stop_signals, &signal);
      if (!finished) std::cerr << "softtune: stopping (signal " << signal << ")\n";
      server.stop();
    });
    std::cout << "softtune: serving http://" << options.host << ':' << port << "/ (Ctrl-C stops)" << std::endl;
    server.run();
    finished = true;
    pthread_kill(waiter.native_handle(), SIGTERM);  // wakes the waiter when run() ended on its own
    waiter.join();
    return kExitOk;
  });
}

}  // namespace softtune::cli
