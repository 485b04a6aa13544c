#include "http/check_routes.h"

#include "app/check_request.h"
#include "codec/json_reader.h"

namespace softtune::http {

HttpResponse check(const HttpRequest& request, Service& service) {
  const app::CheckAnswer answer = app::run_check_request(codec::parse_json(request.body), service.config().presets_dir);
  if (!answer.junit) return json_response(answer.json);
  HttpResponse r;
  r.content_type = "application/xml; charset=utf-8";
  r.body = answer.xml;
  return r;
}

}  // namespace softtune::http
