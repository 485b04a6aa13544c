#include "http/routes.h"

#include "codec/json_reader.h"
#include "codec/tune_codec.h"
#include "http/openapi.h"
#include "http/static_files.h"

namespace softtune::http {
namespace {

HttpResponse health(const HttpRequest&, Service& service) {
  return json_response({{"status", "ok"}, {"service", "softtune"}, {"api", "v1"},
                        {"uptime_seconds", service.uptime_seconds()}});
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
  return serve_static(service.config().web_root, request.path);
}

}  // namespace

Handler json_contract(std::function<nlohmann::json(const nlohmann::json&)> contract) {
  return [contract = std::move(contract)](const HttpRequest& request, Service&) {
    return json_response(contract(codec::parse_json(request.body)));
  };
}

std::vector<Route> service_routes() {
  return {
      {"GET", "/api/v1/health", health},
      {"POST", "/api/v1/tune", json_contract(codec::run_tune)},
      {"GET", "/api/v1/openapi.json", openapi},
      {"GET", "/metrics", metrics},
      {"GET", "/{path...}", static_page},
  };
}

}  // namespace softtune::http
