#pragma once
// POST /api/v1/identify (issue 19): the identify contract as JSON, or a text/csv body (a header row, time
// first) with the engine, what was typed and the tune request in the query
// (?engine=godot&typed_frequency_hz=5&frequency_hz=5&damping_ratio=0.5&effective_mass=2).

#include <string_view>

#include "http/service.h"

namespace softtune::http {

inline constexpr std::string_view kIdentifyPath = "/api/v1/identify";

/// True for "text/csv", with or without parameters ("text/csv; charset=utf-8").
bool is_csv_media_type(std::string_view content_type);

HttpResponse identify(const HttpRequest& request, Service& service);

}  // namespace softtune::http
