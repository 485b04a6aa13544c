#include "http/routes.h"

#include "app/modes_app.h"
#include "app/simulate_app.h"
#include "app/verify_app.h"
#include "codec/json_reader.h"
#include "app/tune_app.h"
#include "codec/tune_codec.h"
#include "http/capability_routes.h"
#include "http/identify_routes.h"
#include "http/job_routes.h"
#include "http/check_routes.h"
#include "http/openapi.h"
#include "http/preview_routes.h"
#include "http/static_files.h"
#include "softtune/version.h"

namespace softtune::http {
namespace {

HttpResponse health(const HttpRequest&, Service& service) {
  return json_response({{"status", "ok"}, {"service", "softtune"}, {"api", "v1"},
                        {"version", std::string(kVersion)}, {"uptime_seconds", service.uptime_seconds()}});
}

// The embedded document: the bytes of server/http/openapi.json, the same ones the tests read.
HttpResponse openapi(const HttpRequest&, Service&) {
  HttpResponse r;
  r.body = std::string(openapi_text());
  return r;
}

HttpResponse metrics(const HttpRequest&, Service& service) {
  HttpResponse r;
  r.content_type = "text/plain; version=0.0.4; charset=utf-8";
  r.body = service.metrics().prometheus_text();
  return r;
}

HttpResponse static_page(const HttpRequest& request, Service& service) {
  return serve_static(service.config().web_root, request.path, request.header("If-None-Match"));
}

// The cache key of a request: numbers as the codec reads them (doubles, so 2 and 2.0 are one request),
// keys sorted by nlohmann's object map, no whitespace.
nlohmann::json canonical(const nlohmann::json& doc) {
  if (doc.is_number()) return doc.get<double>();
  if (doc.is_array() || doc.is_object()) {
    nlohmann::json out = doc;
    for (auto& element : out) element = canonical(element);
    return out;
  }
  return doc;
}

}  // namespace

Handler json_contract(std::function<nlohmann::json(const nlohmann::json&)> contract, std::string cache) {
  return [contract = std::move(contract), cache = std::move(cache)](const HttpRequest& request, Service& service) {
    if (cache.empty()) return json_response(contract(codec::parse_json(request.body)));
    HttpResponse response;
    // A repeat of the very same bytes is found without parsing them (parsing and canonicalising are
    // most of a cache hit's cost). The prefix keeps these keys apart from canonical ones, which
    // never start with "raw".
    const std::string raw_key = cache + "\nraw\n" + request.body;
    if (auto body = service.response_cache().find(raw_key)) {
      service.metrics().record_cache(cache, true);
      response.body = *body;
      return response;
    }
    const nlohmann::json doc = codec::parse_json(request.body);
    const std::string key = cache + '\n' + canonical(doc).dump();
    auto body = service.response_cache().find(key);
    service.metrics().record_cache(cache, body != nullptr);
    if (!body) {
      body = std::make_shared<const std::string>(contract(doc).dump());
      service.response_cache().insert(key, body);
    }
    service.response_cache().insert(raw_key, body);
    response.body = *body;
    return response;
  };
}

std::vector<Route> service_routes() {
  std::vector<Route> routes = {
      {"GET", "/api/v1/health", health},
      {"POST", "/api/v1/tune", json_contract(app::run_tune, "tune")},
      {"POST", "/api/v1/simulate", simulate},
      {"POST", "/api/v1/modes", [](const HttpRequest& request, Service& service) {
         return json_response(app::run_modes(codec::parse_json(request.body), service.config().presets_dir));
       }},
      {"POST", "/api/v1/check", check},
      {"POST", "/api/v1/verify", json_contract(app::run_verify, "")},
      // Its text/csv body takes the other fields from the query (every tune field by name, engine, typed_*):
      // the identify codec reads and names each, and the handler refuses a query beside a JSON body.
      {"POST", std::string(kIdentifyPath), identify, {"*"}},
      {"GET", "/api/v1/presets", presets},
      {"GET", "/api/v1/presets/{name}", preset},
      {"GET", "/api/v1/scene-engines", [](const HttpRequest&, Service&) { return json_response(app::scene_engines_index()); }},
      {"POST", "/api/v1/accuracy", accuracy, {"format"}},
      {"GET", "/api/v1/stability", default_stability(), {"format"}},
      {"POST", "/api/v1/stability", stability, {"format"}},
      {"GET", "/api/v1/openapi.json", openapi},
      {"GET", "/metrics", metrics},
  };
  for (Route& r : preview_routes()) routes.push_back(std::move(r));
  for (Route& r : job_routes()) routes.push_back(std::move(r));
  routes.push_back({"GET", "/{path...}", static_page, {"*"}});  // the static page's catch-all comes last
  return routes;
}

}  // namespace softtune::http
