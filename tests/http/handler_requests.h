#pragma once
// A request as the transport hands it to the handlers, for the tests that call Service::handle directly.

#include <string>

#include "http/http_types.h"

namespace softtune::http::test {

inline HttpRequest request(std::string method, std::string path, std::string body = "") {
  HttpRequest r;
  r.method = std::move(method);
  r.path = std::move(path);
  r.body = std::move(body);
  return r;
}

}  // namespace softtune::http::test
