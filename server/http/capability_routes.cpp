#include "http/capability_routes.h"

#include <memory>
#include <mutex>
#include <optional>

#include "app/accuracy_app.h"
#include "app/stability_app.h"
#include "codec/json_reader.h"
#include "codec/problem.h"
#include "app/simulate_app.h"
#include "codec/scene_codec.h"

namespace softtune::http {
namespace {

/// The ?format= of a request (json when absent), refused (422, field "format") unless one of `allowed`.
app::Format output_format(const HttpRequest& request, std::initializer_list<app::Format> allowed) {
  return app::format_named(request.query_value("format").value_or("json"), allowed, "format");
}

HttpResponse answer_response(const app::Answer& answer) {
  if (answer.format == app::Format::json) return json_response(answer.json);
  HttpResponse r;
  r.content_type = std::string(answer.content_type());
  r.body = answer.text;
  return r;
}

constexpr std::initializer_list<app::Format> kStabilityFormats = {app::Format::json, app::Format::svg};

}  // namespace

HttpResponse simulate(const HttpRequest& request, Service& service) {
  return json_response(app::run_simulate(codec::parse_json(request.body), service.config().presets_dir));
}

HttpResponse presets(const HttpRequest&, Service& service) {
  return json_response(app::presets_index(service.config().presets_dir));
}

HttpResponse preset(const HttpRequest& request, Service& service) {
  try {
    return json_response(app::preset_document(service.config().presets_dir, request.params.at("name")));
  } catch (const codec::Problem& p) {
    // The loader names its own "preset" field; here the name is the path parameter.
    if (p.field != "preset") throw;
    throw codec::Problem(p.status, p.title, "name", p.detail);
  }
}

HttpResponse accuracy(const HttpRequest& request, Service&) {
  const app::Format format = output_format(request, {app::Format::json, app::Format::csv, app::Format::svg});
  return answer_response(app::accuracy_answer(codec::parse_json(request.body), format));
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
    const app::Format format = output_format(request, kStabilityFormats);
    std::lock_guard lock(kept->mutex);
    if (!kept->encoded) kept->encoded = app::run_stability(codec::decode_stability_request(nlohmann::json()));
    std::shared_ptr<const HttpResponse>& answer = format == app::Format::svg ? kept->svg : kept->json;
    if (!answer) {
      app::Answer a;
      a.format = format;
      if (format == app::Format::svg) a.text = app::stability_svg(*kept->encoded);
      else a.json = *kept->encoded;
      answer = std::make_shared<const HttpResponse>(answer_response(a));
    }
    return *answer;
  };
}

HttpResponse stability(const HttpRequest& request, Service& service) {
  const app::Format format = output_format(request, kStabilityFormats);
  const nlohmann::json doc = codec::parse_json(request.body);
  // The codec reads null as the default sweep (GET's request); a POSTed body is an object, as in every contract.
  if (!doc.is_object()) throw codec::invalid_field("", "must be a JSON object ({} for the default sweep)");
  return answer_response(app::stability_answer(codec::decode_stability_request(doc), format, service.config().presets_dir));
}

}  // namespace softtune::http
