#include "http/capability_routes.h"

#include <memory>
#include <mutex>
#include <optional>

#include "box2d_spring.h"
#include "codec/accuracy_codec.h"
#include "codec/json_reader.h"
#include "codec/problem.h"
#include "codec/scene_codec.h"
#include "codec/stability_codec.h"

namespace softtune::http {
namespace {

constexpr const char* kSvg = "image/svg+xml";
constexpr const char* kCsv = "text/csv";

/// The ?format= of a request (json when absent), refused (422, field "format") unless one of `allowed`.
std::string output_format(const HttpRequest& request, std::initializer_list<std::string_view> allowed,
                          const char* rule) {
  const std::string format = request.query_value("format").value_or("json");
  for (std::string_view a : allowed) {
    if (format == a) return format;
  }
  throw codec::invalid_field("format", rule);
}

HttpResponse text_response(std::string body, const char* content_type) {
  HttpResponse r;
  r.content_type = content_type;
  r.body = std::move(body);
  return r;
}

/// The stability answer in the asked format; the SVG needs no per-case list.
HttpResponse stability_response(const nlohmann::json& encoded, const std::string& format) {
  if (format == "svg") return text_response(codec::stability_svg(encoded), kSvg);
  return json_response(encoded);
}

constexpr const char* kStabilityFormats = "must be json or svg";

}  // namespace

HttpResponse simulate(const HttpRequest& request, Service& service) {
  return json_response(codec::run_simulate(codec::parse_json(request.body), service.config().presets_dir));
}

HttpResponse presets(const HttpRequest&, Service& service) {
  return json_response(codec::presets_index(service.config().presets_dir));
}

HttpResponse preset(const HttpRequest& request, Service& service) {
  try {
    return json_response(codec::preset_document(service.config().presets_dir, request.params.at("name")));
  } catch (const codec::Problem& p) {
    // The loader names its own "preset" field; here the name is the path parameter.
    if (p.field != "preset") throw;
    throw codec::Problem(p.status, p.title, "name", p.detail);
  }
}

HttpResponse accuracy(const HttpRequest& request, Service&) {
  const std::string format = output_format(request, {"json", "csv", "svg"}, "must be json, csv or svg");
  const codec::AccuracyRequest q = codec::decode_accuracy_request(codec::parse_json(request.body));
  const AccuracyReport report = codec::run_accuracy_report(q, EngineRunner{kBox2DRowName, run_box2d_spring});
  if (format == "svg") return text_response(codec::accuracy_svg(q, report), kSvg);
  const nlohmann::json encoded = codec::encode_accuracy_report(q, report, q.box2d);
  if (format == "csv") return text_response(codec::accuracy_csv(encoded), kCsv);
  return json_response(encoded);
}

Handler default_stability() {
  // The default sweep takes about a second and never changes: run it once, on the first request (later
  // requests wait for it), and answer every request from that.
  struct Kept {
    std::mutex mutex;
    std::optional<nlohmann::json> encoded;
    std::shared_ptr<const HttpResponse> json, svg;
  };
  auto kept = std::make_shared<Kept>();
  return [kept](const HttpRequest& request, Service&) {
    const std::string format = output_format(request, {"json", "svg"}, kStabilityFormats);
    std::lock_guard lock(kept->mutex);
    if (!kept->encoded) kept->encoded = codec::run_stability(codec::decode_stability_request(nlohmann::json()));
    std::shared_ptr<const HttpResponse>& answer = format == "svg" ? kept->svg : kept->json;
    if (!answer) answer = std::make_shared<const HttpResponse>(stability_response(*kept->encoded, format));
    return *answer;
  };
}

HttpResponse stability(const HttpRequest& request, Service&) {
  const std::string format = output_format(request, {"json", "svg"}, kStabilityFormats);
  codec::StabilityRequest q = codec::decode_stability_request(codec::parse_json(request.body));
  if (format == "svg") q.include_cases = false;
  return stability_response(codec::run_stability(q), format);
}

}  // namespace softtune::http
