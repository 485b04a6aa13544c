#include "http/preview_routes.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <memory>
#include <mutex>

#include "codec/json_reader.h"
#include "app/preview_service.h"
#include "codec/problem.h"
#include "http/conditional.h"
#include "http/limits.h"
#include "app/budgets.h"
#include "softtune/support/sanitizer_build.h"

namespace softtune::http {
namespace {

constexpr const char* kPrefix = "/api/v1/preview";

// One PreviewService per route table, made when first needed.
class LazyPreviews {
 public:
  /// The service, made on the first call (its caches then show in `metrics`).
  app::PreviewService& get(Metrics* metrics = nullptr) {
    std::call_once(once_, [this, metrics] {
      // A preview's frames render on the pool, not on the request's thread: they are held to the same
      // limit as a request's run (kRunLimitFactor x its budget), summed over their frames.
      render::PipelineOptions options;
      options.job_cpu_seconds =
          limits::kRunLimitFactor * app::budgets::kCpuSeconds * support::kInstrumentationSlowdown;
      service_ = std::make_unique<app::PreviewService>(options);
      if (metrics) {
        metrics->add_cache_gauge("preview_frames", [this] {
          const support::LruStats s = service_->cache_stats();
          return Metrics::CacheSize{s.entries, s.bytes};
        });
        metrics->add_cache_gauge("preview_clips", [this] {
          const support::LruStats s = service_->clip_cache_stats();
          return Metrics::CacheSize{s.entries, s.bytes};
        });
      }
      started_.store(true, std::memory_order_release);
    });
    return *service_;
  }
  /// False until the first preview request: GETs before it find nothing and start nothing.
  bool started() const { return started_.load(std::memory_order_acquire); }

 private:
  std::once_flag once_;
  std::atomic<bool> started_{false};
  std::unique_ptr<app::PreviewService> service_;
};

codec::Problem not_found(const std::string& what) { return codec::Problem(404, "Not found", "id", what); }

// A preview id is the SHA-256 of its request (render::FramePipeline::preview_id): 64 lower-case hex
// digits. Anything else names no preview, and is not echoed (a 5000-character id made a 5 KB 404).
constexpr std::size_t kIdLength = 64;

const std::string& checked_preview_id(const HttpRequest& request) {
  const std::string& id = request.params.at("id");
  const bool valid = id.size() == kIdLength &&
                     std::all_of(id.begin(), id.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
  if (!valid) throw not_found("no such preview: a preview id is 64 lower-case hex digits, as POST /api/v1/preview gives it");
  return id;
}

// A content-addressed image (PNG or clip): the same URL always names the same bytes.
HttpResponse image(const HttpRequest& request, std::string bytes, const std::string& etag, std::string_view type) {
  HttpResponse r;
  r.headers.emplace_back("ETag", etag);
  r.headers.emplace_back("Cache-Control", "public, max-age=31536000, immutable");
  if (const auto tags = request.header("If-None-Match"); tags && if_none_match(*tags, etag)) {
    r.status = 304;
    r.content_type.clear();
    return r;
  }
  r.content_type = std::string(type);
  r.body = std::move(bytes);
  return r;
}

HttpResponse png(const HttpRequest& request, std::string bytes, const std::string& etag) {
  return image(request, std::move(bytes), etag, "image/png");
}

// GET .../animation.webp or .gif: the clip, made from the cached frames on first ask.
Route clip_route(const std::shared_ptr<LazyPreviews>& previews, render::ClipFormat format) {
  const std::string name = std::string(render::clip_format_name(format));
  return {"GET", std::string(kPrefix) + "/{id}/animation." + name,
          [previews, format, name](const HttpRequest& request, Service&) {
            const std::string& id = checked_preview_id(request);
            auto bytes = previews->started() ? previews->get().clip(id, format) : std::nullopt;
            if (!bytes) throw not_found("no finished preview " + id);
            return image(request, std::move(*bytes), "\"" + id + "-animation-" + name + "\"",
                         render::clip_content_type(format));
          }};
}

// Frame numbers are written one way (0, 1, ..., no sign, no leading zeros): /00.png would be a second URL
// for the bytes of /0.png, and a content-addressed, immutable URL names its bytes once.
int frame_index(const std::string& text) {
  int n = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n < 0 || text.size() > 6) {
    throw codec::invalid_field("n", "must be a frame number (0, 1, ...)");
  }
  if (text.size() > 1 && text.front() == '0') {
    throw codec::Problem(404, "Not found", "n", "frame numbers have no leading zeros: ask for " + std::to_string(n) + ".png");
  }
  return n;
}

}  // namespace

std::vector<Route> preview_routes() {
  auto previews = std::make_shared<LazyPreviews>();
  return {
      {"POST", "/api/v1/preview",
       [previews](const HttpRequest& request, Service& service) {
         return json_response(
             previews->get(&service.metrics()).start(codec::parse_json(request.body), service.config().presets_dir, kPrefix));
       }},
      {"GET", "/api/v1/preview/{id}",
       [previews](const HttpRequest& request, Service&) {
         const std::string& id = checked_preview_id(request);
         auto status = previews->started() ? previews->get().status(id, kPrefix) : std::nullopt;
         if (!status) throw not_found("no preview " + id + " (they are kept in a bounded cache; ask again)");
         return json_response(*status);
       }},
      {"GET", "/api/v1/preview/{id}/filmstrip.png",
       [previews](const HttpRequest& request, Service&) {
         const std::string& id = checked_preview_id(request);
         auto bytes = previews->started() ? previews->get().filmstrip_png(id) : std::nullopt;
         if (!bytes) throw not_found("no finished preview " + id);
         return png(request, std::move(*bytes), "\"" + id + "-filmstrip\"");
       }},
      {"GET", "/api/v1/preview/{id}/{n}.png",
       [previews](const HttpRequest& request, Service&) {
         const std::string& id = checked_preview_id(request);
         const int n = frame_index(request.params.at("n"));
         auto bytes = previews->started() ? previews->get().frame_png(id, n) : std::nullopt;
         if (!bytes) throw not_found("no frame " + std::to_string(n) + " of preview " + id);
         return png(request, std::move(*bytes), "\"" + id + "-" + std::to_string(n) + "\"");
       }},
      clip_route(previews, render::ClipFormat::webp),
      clip_route(previews, render::ClipFormat::gif),
  };
}

}  // namespace softtune::http
