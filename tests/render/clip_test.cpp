// Clips (render/src/clip.cpp, clip_webp.cpp, clip_gif.cpp): decoded back with libwebp's own demuxer
// (WebPAnimDecoder) and giflib's reader, they hold the right frame count, size, timing and pixels.
#include "softtune/render/clip.h"

#include <gif_lib.h>
#include <gtest/gtest.h>
#include <webp/demux.h>

#include <cstdlib>
#include <cstring>
#include <functional>

#include "softtune/render/palette.h"
#include "softtune/render/png.h"
#include "softtune/support/run_limit.h"

namespace softtune::render {
namespace {

// Frame k: a grey background with a black square at x = 4 k (so every frame differs).
std::vector<std::string> moving_square(int frames, ImageSize size) {
  std::vector<std::string> out;
  for (int k = 0; k < frames; ++k) {
    std::vector<std::uint8_t> rgba(rgba_bytes(size), 246);
    for (int y = 10; y < 30; ++y) {
      for (int x = 4 * k; x < 4 * k + 20 && x < size.width; ++x) {
        std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * size.width + x) * 4];
        p[0] = p[1] = p[2] = 20;
      }
    }
    for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
    out.push_back(encode_png(rgba, size));
  }
  return out;
}

// Each image of a slurped GIF over the one before, as a browser shows it (DISPOSE_DO_NOT).
std::vector<std::vector<GifColorType>> composite(GifFileType* g) {
  std::vector<std::vector<GifColorType>> out;
  std::vector<GifColorType> canvas(static_cast<std::size_t>(g->SWidth) * g->SHeight, GifColorType{0, 0, 0});
  for (int i = 0; i < g->ImageCount; ++i) {
    GraphicsControlBlock gcb;
    DGifSavedExtensionToGCB(g, i, &gcb);
    const GifImageDesc& d = g->SavedImages[i].ImageDesc;
    for (int y = 0; y < d.Height; ++y) {
      for (int x = 0; x < d.Width; ++x) {
        const int index = g->SavedImages[i].RasterBits[y * d.Width + x];
        if (index == gcb.TransparentColor) continue;
        canvas[static_cast<std::size_t>(d.Top + y) * g->SWidth + d.Left + x] = g->SColorMap->Colors[index];
      }
    }
    out.push_back(canvas);
  }
  return out;
}

struct WebpFrames {
  int width = 0, height = 0, loop = -1;
  std::vector<int> end_ms;  // WebPAnimDecoder's timestamps: when each frame ends
  std::vector<std::vector<std::uint8_t>> rgba;
};

WebpFrames decode_webp(const std::string& bytes) {
  WebPData data{reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  WebPAnimDecoderOptionsInit(&options);
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* dec = WebPAnimDecoderNew(&data, &options);
  EXPECT_NE(dec, nullptr);
  WebpFrames out;
  if (!dec) return out;
  WebPAnimInfo info;
  WebPAnimDecoderGetInfo(dec, &info);
  out.width = static_cast<int>(info.canvas_width);
  out.height = static_cast<int>(info.canvas_height);
  out.loop = static_cast<int>(info.loop_count);
  while (WebPAnimDecoderHasMoreFrames(dec)) {
    std::uint8_t* px = nullptr;
    int ts = 0;
    if (!WebPAnimDecoderGetNext(dec, &px, &ts)) break;
    out.end_ms.push_back(ts);
    out.rgba.emplace_back(px, px + static_cast<std::size_t>(out.width) * out.height * 4);
  }
  WebPAnimDecoderDelete(dec);
  return out;
}

TEST(FrameDurations, FollowTheRunsTimesWithoutDrift) {
  // 1/60 s frames: 17, 16, 17, ... ms, summing to the true 1000 ms over 60 frames.
  std::vector<double> t;
  for (int i = 0; i <= 60; ++i) t.push_back(i / 60.0);
  const std::vector<int> d = frame_durations_ms(t);
  int sum = 0;
  for (std::size_t i = 0; i + 1 < d.size(); ++i) {
    EXPECT_TRUE(d[i] == 16 || d[i] == 17) << i;
    sum += d[i];
  }
  EXPECT_EQ(sum, 1000);
  EXPECT_EQ(d.back(), d[d.size() - 2]);
  EXPECT_EQ(frame_durations_ms({0.0, 0.0, 0.5}), (std::vector<int>{1, 499, 499}));
}

TEST(Clip, WebpDecodesToTheFramesWithTheirTiming) {
  const ImageSize size{96, 40};
  const auto frames = moving_square(12, size);
  std::vector<double> t;
  for (int i = 0; i < 12; ++i) t.push_back(0.1 * i);  // a scene snapshotted every 6 frames at 60 fps
  const std::string webp = encode_clip(ClipFormat::webp, frames, t);
  ASSERT_EQ(webp.compare(0, 4, "RIFF"), 0);
  const WebpFrames got = decode_webp(webp);
  EXPECT_EQ(got.width, 96);
  EXPECT_EQ(got.height, 40);
  EXPECT_EQ(got.loop, 0);
  ASSERT_EQ(got.end_ms.size(), 12u);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(got.end_ms[i], 100 * (i + 1)) << i;
  // Lossless on the GIF's palette: every pixel comes back as its nearest palette colour, within a few
  // levels of what went in (the square's 20 grey is the anchor colour 20, 22, 28; the 246 grey the
  // background 246, 246, 242).
  for (int i = 0; i < 12; ++i) {
    ImageSize s;
    const std::vector<std::uint8_t> source = decode_png(frames[i], s);
    for (std::size_t p = 0; p < source.size(); p += 4) {
      ASSERT_LE(std::abs(got.rgba[i][p] - source[p]) + std::abs(got.rgba[i][p + 1] - source[p + 1]) +
                    std::abs(got.rgba[i][p + 2] - source[p + 2]),
                16)
          << "frame " << i << " pixel " << p / 4;
      ASSERT_EQ(got.rgba[i][p + 3], 255);
    }
  }
}

TEST(Clip, WebpKeepsThePalettesOwnColoursExactAndExactModeEveryColour) {
  // A frame in the preview palette's own colours (background, a dynamic body, a stretched spring) comes
  // back exactly; without the palette (WebpClipOptions::palette false) any colour does.
  const ImageSize size{64, 32};
  std::vector<std::vector<std::uint8_t>> frames;
  for (int k = 0; k < 4; ++k) {
    std::vector<std::uint8_t> rgba(rgba_bytes(size));
    for (int p = 0; p < size.width * size.height; ++p) {
      const int x = p % size.width;
      const Rgba c = x < 8 * k ? role_colours(Role::dynamic_body).fill : x < 8 * k + 4 ? palette::kSpringStretched : palette::kBackground;
      rgba[4 * p] = c.r, rgba[4 * p + 1] = c.g, rgba[4 * p + 2] = c.b, rgba[4 * p + 3] = 255;
    }
    frames.push_back(rgba);
  }
  const auto encode = [&](const WebpClipOptions& o) {
    auto e = make_clip_encoder(ClipFormat::webp, size, {0.0, 0.1, 0.2, 0.3}, o);
    for (const auto& f : frames) e->add(f);
    return decode_webp(e->finish());
  };
  const WebpFrames on_palette = encode({});
  ASSERT_EQ(on_palette.rgba.size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(on_palette.rgba[k], frames[k]) << "frame " << k;
  // Off the palette: a grey ramp no palette holds, exact without it.
  for (auto& f : frames) {
    for (std::size_t p = 0; p < f.size(); p += 4) f[p] = f[p + 1] = f[p + 2] = static_cast<std::uint8_t>((p / 4) % 251);
  }
  WebpClipOptions exact;
  exact.palette = false;
  const WebpFrames got = encode(exact);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(got.rgba[k], frames[k]) << "frame " << k;
}

TEST(Clip, GifDecodesToTheFramesWithCentisecondDelays) {
  const ImageSize size{96, 40};
  const auto frames = moving_square(10, size);
  std::vector<double> t;
  for (int i = 0; i < 10; ++i) t.push_back(0.1 * i);
  const std::string gif = encode_clip(ClipFormat::gif, frames, t);
  ASSERT_EQ(gif.compare(0, 6, "GIF89a"), 0);
  struct Reader {
    const std::string* bytes;
    std::size_t at = 0;
  } reader{&gif};
  int error = 0;
  GifFileType* g = DGifOpen(&reader, [](GifFileType* f, GifByteType* buf, int n) {
    auto* r = static_cast<Reader*>(f->UserData);
    const int take = static_cast<int>(std::min<std::size_t>(n, r->bytes->size() - r->at));
    std::memcpy(buf, r->bytes->data() + r->at, take);
    r->at += take;
    return take;
  }, &error);
  ASSERT_NE(g, nullptr);
  ASSERT_EQ(DGifSlurp(g), GIF_OK);
  EXPECT_EQ(g->SWidth, 96);
  EXPECT_EQ(g->SHeight, 40);
  ASSERT_EQ(g->ImageCount, 10);
  for (int i = 0; i < g->ImageCount; ++i) {
    GraphicsControlBlock gcb;
    ASSERT_EQ(DGifSavedExtensionToGCB(g, i, &gcb), GIF_OK);
    EXPECT_EQ(gcb.DelayTime, 10) << i;
  }
  // Played back as a decoder does (each image over the last at its offset, its transparent index
  // leaving the pixel below), every frame is the source frame: the square dark, the background light.
  const std::vector<std::vector<GifColorType>> shown = composite(g);
  for (int i = 0; i < 10; ++i) {
    ImageSize s;
    const std::vector<std::uint8_t> source = decode_png(frames[i], s);
    for (int p = 0; p < 96 * 40; ++p) {
      const GifColorType c = shown[i][p];
      ASSERT_LE(std::abs(c.Red - source[4 * p]) + std::abs(c.Green - source[4 * p + 1]) + std::abs(c.Blue - source[4 * p + 2]), 16)
          << "frame " << i << " pixel " << p % 96 << "," << p / 96;
    }
  }
  // After the first, a frame holds only the box the square left and entered: 24 x 20 pixels.
  for (int i = 1; i < 10; ++i) {
    EXPECT_EQ(g->SavedImages[i].ImageDesc.Width, 24) << i;
    EXPECT_EQ(g->SavedImages[i].ImageDesc.Height, 20) << i;
  }
  DGifCloseFile(g, &error);
}

TEST(Clip, GifOfStillFramesIsSmallAndStill) {
  // Frame differencing: 20 identical frames cost one full image and 19 one-pixel ones.
  const ImageSize size{320, 180};
  std::vector<std::string> frames(20, moving_square(1, size).front());
  std::vector<double> t;
  for (int i = 0; i < 20; ++i) t.push_back(0.1 * i);
  const std::string one = encode_clip(ClipFormat::gif, {frames.front()}, {0.0});
  const std::string gif = encode_clip(ClipFormat::gif, frames, t);
  EXPECT_LT(gif.size(), one.size() + 19 * 40);
}

TEST(Clip, GifMergesFramesUnderTwoCentiseconds) {
  // 60 fps frames (1.67 cs) would be slowed to 10 cs by browsers. Frame starts round to 0, 2, 3, 5, 7, 8,
  // 10, 12, 13, 15, 17, 18 cs; a frame is kept once 2 cs have passed since the last kept one (0, 2, 5, 7,
  // 10, 12, 15, 17), each lasting 2 or 3 cs, and the clip still lasts the run's 0.2 s.
  const auto frames = moving_square(12, {64, 40});
  std::vector<double> t;
  for (int i = 0; i < 12; ++i) t.push_back(i / 60.0);
  const std::string gif = encode_clip(ClipFormat::gif, frames, t);
  struct Reader {
    const std::string* bytes;
    std::size_t at = 0;
  } reader{&gif};
  int error = 0;
  GifFileType* g = DGifOpen(&reader, [](GifFileType* f, GifByteType* buf, int n) {
    auto* r = static_cast<Reader*>(f->UserData);
    const int take = static_cast<int>(std::min<std::size_t>(n, r->bytes->size() - r->at));
    std::memcpy(buf, r->bytes->data() + r->at, take);
    r->at += take;
    return take;
  }, &error);
  ASSERT_NE(g, nullptr);
  ASSERT_EQ(DGifSlurp(g), GIF_OK);
  EXPECT_EQ(g->ImageCount, 8);
  int total = 0;
  for (int i = 0; i < g->ImageCount; ++i) {
    GraphicsControlBlock gcb;
    DGifSavedExtensionToGCB(g, i, &gcb);
    EXPECT_EQ(gcb.DelayTime, i % 2 == 0 ? 2 : 3) << i;
    total += gcb.DelayTime;
  }
  EXPECT_EQ(total, 20);  // 12 frames of 1/60 s = 0.2 s
  DGifCloseFile(g, &error);
}

TEST(Clip, CapsAndBadInput) {
  EXPECT_FALSE(validate_clip(120, {1280, 720}));
  const auto e = validate_clip(121, {1280, 720});
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "frames");
  EXPECT_TRUE(validate_clip(0, {640, 360}));
  EXPECT_THROW(encode_clip(ClipFormat::webp, {}, {}), std::invalid_argument);
  auto frames = moving_square(2, {32, 32});
  frames.push_back(moving_square(1, {48, 32}).front());
  EXPECT_THROW(encode_clip(ClipFormat::gif, frames, {0.0, 0.1, 0.2}), std::invalid_argument);
  EXPECT_THROW(encode_clip(ClipFormat::webp, moving_square(2, {32, 32}), {0.0}), std::invalid_argument);
  EXPECT_EQ(clip_format("webp"), ClipFormat::webp);
  EXPECT_EQ(clip_format("gif"), ClipFormat::gif);
  EXPECT_FALSE(clip_format("mp4"));
}

}  // namespace
}  // namespace softtune::render

namespace softtune::render {
namespace {

double clip_test_cpu_of(const std::function<void()>& work) {
  const double t0 = support::thread_cpu_seconds();
  work();
  return support::thread_cpu_seconds() - t0;
}

}  // namespace

// A clip encodes under its caller's run-time limit (support/run_limit.h), checked once per frame: a WebP
// that takes far longer than the limit stops within about one frame of it with RunStopped (the HTTP
// service's 422), and encodes whole without one.
TEST(Clip, EncodingStopsAtTheRunLimit) {
  const ImageSize size{640, 360};
  const std::vector<std::string> frames = moving_square(40, size);
  const std::vector<double> times = [] {
    std::vector<double> t(40);
    for (int i = 0; i < 40; ++i) t[i] = i / 60.0;
    return t;
  }();
  double whole = 0.0, one_frame = 0.0;
  whole = clip_test_cpu_of([&] { EXPECT_FALSE(encode_clip(ClipFormat::webp, frames, times).empty()); });
  one_frame = whole / 40;
  const double limit = whole / 8;  // the whole clip takes 8 times the limit
  bool stopped = false;
  const double spent = clip_test_cpu_of([&] {
    const support::ScopedRunLimit scoped({limit, nullptr, {}});
    try {
      encode_clip(ClipFormat::webp, frames, times);
    } catch (const support::RunStopped& e) {
      stopped = e.why == support::RunStopped::Why::budget;
      EXPECT_GT(e.cpu_seconds, limit);
    }
  });
  EXPECT_TRUE(stopped) << "the whole clip took " << whole << " s of CPU, the limit was " << limit << " s";
  // Stopped within the limit plus a few frames (the clocks are read every 10 ms) and the encoder's teardown.
  EXPECT_LT(spent, limit + 4 * one_frame + 0.02) << "whole clip " << whole << " s, limit " << limit << " s";
  EXPECT_LT(spent, whole / 2);
}

}  // namespace softtune::render
