#include "codec/preview_codec.h"

#include <charconv>

#include "codec/json_writer.h"
#include "codec/problem.h"

namespace softtune::codec {

namespace {

std::optional<int> parse_positive(std::string_view s) {
  int v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || s.empty() || v <= 0) return std::nullopt;
  return v;
}

}  // namespace

std::optional<render::ImageSize> parse_image_size(std::string_view text) {
  const auto x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto w = parse_positive(text.substr(0, x)), h = parse_positive(text.substr(x + 1));
  if (!w || !h) return std::nullopt;
  return render::ImageSize{*w, *h};
}

render::PreviewSettings read_preview_settings(ObjectReader& r) {
  render::PreviewSettings s;
  auto bounded_int = [&r](std::string_view key, long long lo, long long hi) -> std::optional<int> {
    const auto v = r.integer(key);
    if (!v) return std::nullopt;
    if (*v < lo || *v > hi) {
      throw invalid_field(r.field(key), "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
    }
    return static_cast<int>(*v);
  };
  if (auto v = bounded_int("frames", 1, render::caps::kMaxFrames)) s.frames = *v;
  if (auto v = bounded_int("filmstrip_every", 0, render::caps::kMaxFrames)) s.filmstrip_every = *v;
  if (auto text = r.string("size")) {
    const auto size = parse_image_size(*text);
    if (!size) throw invalid_field(r.field("size"), "must be \"WxH\" in pixels, e.g. \"640x360\"");
    s.size = *size;
  }
  if (auto e = render::validate_preview_settings(s)) throw invalid_field(r.field(e->field), e->rule);
  return s;
}

std::string canonical_oscillator_request(const render::OscillatorScene& s) {
  const nlohmann::json doc = {
      {"preset", "oscillator"},   {"effective_mass", s.mass_kg}, {"omega", s.omega},
      {"damping_ratio", s.damping_ratio}, {"fps", s.fps},       {"substeps", s.substeps},
      {"method", std::string(method_name(s.method))}, {"initial_displacement", s.initial_displacement_m},
      {"rest_length", s.rest_length_m}, {"duration_s", s.duration_s},
  };
  return doc.dump();  // keys sorted, doubles written to round-trip
}

nlohmann::json encode_frame_manifest(const render::Preview& p, const std::function<std::string(int frame)>& frame_file) {
  nlohmann::json frames = nlohmann::json::array();
  const int n = static_cast<int>(p.frames_png.size());
  for (int i = 0; i < n; ++i) {
    const double t = i < static_cast<int>(p.frame_times_s.size()) ? p.frame_times_s[i] : 0.0;
    frames.push_back({{"index", i}, {"file", frame_file(i)}, {"time_s", number_or_null(t)}});
  }
  const double first = n > 0 && !p.frame_times_s.empty() ? p.frame_times_s.front() : 0.0;
  const double last = n > 0 && !p.frame_times_s.empty() ? p.frame_times_s.back() : 0.0;
  return {{"frame_count", n},
          {"run_end_s", number_or_null(p.run_end_s)},
          {"frame_dt_s", number_or_null(n > 1 ? (last - first) / (n - 1) : 0.0)},
          {"frames", std::move(frames)}};
}

nlohmann::json encode_preview(const render::Preview& p, bool from_cache,
                              const std::function<std::string(int frame)>& frame_url, const std::string& filmstrip_url) {
  nlohmann::json frames = nlohmann::json::array();
  for (int i = 0; i < static_cast<int>(p.frames_png.size()); ++i) frames.push_back(frame_url(i));
  const render::PreviewTimings& t = p.timings;
  return {
      {"id", p.id},
      {"cached", from_cache},
      {"frames", std::move(frames)},
      {"filmstrip", filmstrip_url},
      {"size", std::to_string(p.settings.size.width) + "x" + std::to_string(p.settings.size.height)},
      {"frame_count", p.settings.frames},
      {"filmstrip_every", p.filmstrip.every},
      {"stages", from_cache ? nlohmann::json::array() : stages_json(p.stages)},  // a cache hit ran nothing
      {"timings", {{"wall_ms", number_or_null(t.wall_ms)},
                   {"prepare_ms", number_or_null(t.prepare_ms)},
                   {"render_ms", number_or_null(t.render_ms)},
                   {"png_ms", number_or_null(t.png_ms)},
                   {"filmstrip_ms", number_or_null(t.filmstrip_ms)},
                   {"clip_ms", number_or_null(t.clip_ms)},
                   {"clip_tail_ms", number_or_null(t.clip_tail_ms)},
                   {"workers", t.workers}}},
  };
}

}  // namespace softtune::codec
