#pragma once
// The preview routes: POST /api/v1/preview, GET /api/v1/preview/{id} (progress, or the finished answer),
// GET /api/v1/preview/{id}/{n}.png and /filmstrip.png (immutable, ETag from the content hash).

#include <vector>

#include "http/service.h"

namespace softtune::http {

/// The rows for the route table. They share one frame pipeline, created on the first preview request,
/// so a server that is never asked for frames starts no render thread and no GL context.
std::vector<Route> preview_routes();

}  // namespace softtune::http
