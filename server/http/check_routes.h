#pragma once
// POST /api/v1/check: the preset test of `softtune check`, on the server (app/check_request.h), so a
// studio's tool can run checks without the binary. docs/preset-ci.md.

#include "http/service.h"

namespace softtune::http {

/// POST /api/v1/check: app::run_check_request with the service's presets directory; the JSON report, or
/// JUnit XML (application/xml) for "format": "junit". 200 whether the checks pass or fail (the report says);
/// 422 for bad input and for work above the budget.
HttpResponse check(const HttpRequest& request, Service& service);

}  // namespace softtune::http
