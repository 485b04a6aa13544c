#pragma once
// Handlers of the capabilities shared with the CLI beyond tune: simulate, presets, accuracy and
// stability (docs/api.md, "HTTP API"). Each runs the same codec function as its CLI command, so one
// request gives the same JSON on both.

#include "http/service.h"

namespace softtune::http {

/// POST /api/v1/simulate: app::run_simulate with the service's presets directory.
HttpResponse simulate(const HttpRequest& request, Service& service);

/// GET /api/v1/presets: app::presets_index.
HttpResponse presets(const HttpRequest& request, Service& service);

/// GET /api/v1/presets/{name}: app::preset_document; 404 for an unknown name, 422 (field "name")
/// for a name that is not 1 to 64 of [a-z0-9_-].
HttpResponse preset(const HttpRequest& request, Service& service);

/// POST /api/v1/accuracy[?format=json|csv|svg]: the work-precision report with the Box2D row, as
/// `softtune accuracy`. Never cached: the rows carry measured CPU time.
HttpResponse accuracy(const HttpRequest& request, Service& service);

/// GET /api/v1/stability[?format=json|svg]: the default sweep, computed on the first request and kept
/// (it is deterministic: no timing field). Each call of this function makes a handler with its own copy.
Handler default_stability();

/// POST /api/v1/stability[?format=json|svg]: a custom sweep, as `softtune stability --request`.
HttpResponse stability(const HttpRequest& request, Service& service);

}  // namespace softtune::http
