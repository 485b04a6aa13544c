// The OSMesa backend: the only file that includes GL headers. GL 3.3 core on llvmpipe; the mesh comes
// from tessellate(), so a replacement backend only has to draw coloured triangles and read pixels back.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <atomic>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>

#include "softtune/render/palette.h"
#include "softtune/render/renderer.h"
#include "softtune/render/tessellate.h"

namespace softtune::render {
namespace {

std::atomic<int> g_contexts_created{0};

// Context creation and the first draw (which JIT-compiles llvmpipe's shader variants) touch Mesa's and
// LLVM's process-wide state; they happen once per worker, so they are serialized.
std::mutex g_setup_mutex;

// Pixel positions map to NDC with y NOT flipped: pixel row 0 lands in GL row 0, which glReadPixels
// returns first, so the read-back image is top-down without a copy.
constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position_px;
layout(location = 1) in vec4 colour;
uniform vec2 inverse_size;
out vec4 v_colour;
void main() {
  gl_Position = vec4(position_px * 2.0 * inverse_size - 1.0, 0.0, 1.0);
  v_colour = colour;
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec4 v_colour;
out vec4 out_colour;
void main() { out_colour = v_colour; }
)";

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    throw std::runtime_error(std::string("render: shader does not compile: ") + log);
  }
  return shader;
}

class OsMesaRenderer final : public Renderer {
 public:
  explicit OsMesaRenderer(RendererOptions options) : options_(options) {}

  ~OsMesaRenderer() override {
    if (context_) OSMesaDestroyContext(context_);
  }

  void render(const DrawFrame& frame, const Camera& camera, ImageSize size, std::span<std::uint8_t> rgba) override {
    if (size.width <= 0 || size.height <= 0 ||
        rgba.size() != static_cast<std::size_t>(size.width) * static_cast<std::size_t>(size.height) * 4) {
      throw std::invalid_argument("render: the pixel buffer does not match the image size");
    }
    make_current();
    draw(frame, camera, size, rgba);
  }

 private:
  void draw(const DrawFrame& frame, const Camera& camera, ImageSize size, std::span<std::uint8_t> rgba) {
    ensure_targets(size);
    const View view = make_view(resolve_camera(camera, frame, size), size);
    tessellate(frame, view, options_.msaa_samples == 0, mesh_);

    glBindFramebuffer(GL_FRAMEBUFFER, options_.msaa_samples > 0 ? msaa_fbo_ : resolve_fbo_);
    glViewport(0, 0, size.width, size.height);
    const Rgba bg = palette::kBackground;
    glClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(program_);
    glUniform2f(inverse_size_, 1.0f / size.width, 1.0f / size.height);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh_.vertices.size() * sizeof(Vertex)),
                 mesh_.vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(mesh_.vertices.size()));
    if (options_.msaa_samples > 0) {
      glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo_);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
      glBlitFramebuffer(0, 0, size.width, size.height, 0, 0, size.width, size.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo_);
    glReadPixels(0, 0, size.width, size.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
      throw std::runtime_error("render: GL error " + std::to_string(e));
    }
    draw_text_overlay(frame, view, rgba);
  }

  void make_current() {
    if (!context_) {
      std::lock_guard lock(g_setup_mutex);
      try {
        create_context();
        warm_up();
      } catch (...) {
        // A half-made context must not be reused: the next frame tries again from scratch.
        if (context_) OSMesaDestroyContext(context_);
        context_ = nullptr;
        program_ = vao_ = vbo_ = msaa_fbo_ = msaa_rb_ = resolve_fbo_ = resolve_rb_ = 0;
        target_size_ = {0, 0};
        throw;
      }
    }
    if (OSMesaGetCurrentContext() != context_ &&
        !OSMesaMakeCurrent(context_, dummy_, GL_UNSIGNED_BYTE, 1, 1)) {
      throw std::runtime_error("render: OSMesaMakeCurrent failed");
    }
  }

  void create_context() {
    // llvmpipe reads LP_NUM_THREADS when it starts; a value in the environment wins.
    static std::once_flag env_once;
    std::call_once(env_once, [this] {
      setenv("LP_NUM_THREADS", std::to_string(options_.llvmpipe_threads).c_str(), 0);
    });
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw std::runtime_error("render: OSMesa cannot create a GL 3.3 core context");
    g_contexts_created.fetch_add(1, std::memory_order_relaxed);
    if (!OSMesaMakeCurrent(context_, dummy_, GL_UNSIGNED_BYTE, 1, 1)) {
      throw std::runtime_error("render: OSMesaMakeCurrent failed");
    }
    program_ = glCreateProgram();
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader), fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &linked);
    if (!linked) throw std::runtime_error("render: shader program does not link");
    inverse_size_ = glGetUniformLocation(program_, "inverse_size");

    glGenVertexArrays(1, &vao_);
    glGenBuffers(1, &vbo_);
    glBindVertexArray(vao_);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, x)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                          reinterpret_cast<void*>(offsetof(Vertex, colour)));
    // Straight-alpha "over" for colour; alpha accumulates so the target stays opaque.
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
  }

  // One small frame so the shader variants exist before the first real frame runs unserialized.
  void warm_up() {
    constexpr ImageSize kTiny{16, 16};
    std::uint8_t pixels[kTiny.width * kTiny.height * 4];
    DrawFrame frame;
    frame.polygons.push_back({{{-1.0, -1.0}, {1.0, -1.0}, {0.0, 1.0}}, Role::dynamic_body});
    Camera camera;
    camera.auto_fit = false;
    draw(frame, camera, kTiny, pixels);
  }

  void ensure_targets(ImageSize size) {
    if (size == target_size_) return;
    glDeleteFramebuffers(1, &msaa_fbo_);
    glDeleteFramebuffers(1, &resolve_fbo_);
    glDeleteRenderbuffers(1, &msaa_rb_);
    glDeleteRenderbuffers(1, &resolve_rb_);
    msaa_fbo_ = msaa_rb_ = 0;
    glGenFramebuffers(1, &resolve_fbo_);
    glGenRenderbuffers(1, &resolve_rb_);
    attach(resolve_fbo_, resolve_rb_, 0, size);
    if (options_.msaa_samples > 0) {
      glGenFramebuffers(1, &msaa_fbo_);
      glGenRenderbuffers(1, &msaa_rb_);
      attach(msaa_fbo_, msaa_rb_, options_.msaa_samples, size);
    }
    target_size_ = size;
  }

  static void attach(GLuint fbo, GLuint rb, int samples, ImageSize size) {
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, size.width, size.height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      throw std::runtime_error("render: off-screen framebuffer incomplete");
    }
  }

  RendererOptions options_;
  OSMesaContext context_ = nullptr;
  unsigned char dummy_[4] = {};  // OSMesa wants a default colour buffer; frames go to the FBOs
  GLuint program_ = 0, vao_ = 0, vbo_ = 0;
  GLint inverse_size_ = -1;
  GLuint msaa_fbo_ = 0, msaa_rb_ = 0, resolve_fbo_ = 0, resolve_rb_ = 0;
  ImageSize target_size_{0, 0};
  Mesh mesh_;
};

}  // namespace

std::unique_ptr<Renderer> make_osmesa_renderer(RendererOptions options) {
  return std::make_unique<OsMesaRenderer>(options);
}

int gl_contexts_created() { return g_contexts_created.load(std::memory_order_relaxed); }

}  // namespace softtune::render
