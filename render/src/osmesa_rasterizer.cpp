// The OSMesa backend: the only file that includes GL headers. GL 3.3 core on llvmpipe; the mesh comes
// from tessellate() in the calling process, so a replacement backend (EGL surfaceless: Mesa 25.1 removed
// OSMesa) only has to draw coloured triangles and read pixels back.
#define GL_GLEXT_PROTOTYPES
#include "osmesa_rasterizer.h"

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <stdexcept>
#include <string>

#include "softtune/render/palette.h"

namespace softtune::render {
namespace {

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

void attach(GLuint fbo, GLuint rb, int samples, ImageSize size) {
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, size.width, size.height);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("render: off-screen framebuffer incomplete");
  }
}

}  // namespace

struct OsmesaRasterizer::Gl {
  OSMesaContext context = nullptr;
  unsigned char dummy[4] = {};  // OSMesa wants a default colour buffer; frames go to the FBOs
  GLuint program = 0, vao = 0, vbo = 0;
  GLint inverse_size = -1;
  GLuint msaa_fbo = 0, msaa_rb = 0, resolve_fbo = 0, resolve_rb = 0;
  ImageSize target_size{0, 0};

  ~Gl() {
    if (context) OSMesaDestroyContext(context);
  }

  void create_context() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                              OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context) throw std::runtime_error("render: OSMesa cannot create a GL 3.3 core context");
    if (!OSMesaMakeCurrent(context, dummy, GL_UNSIGNED_BYTE, 1, 1)) {
      throw std::runtime_error("render: OSMesaMakeCurrent failed");
    }
    program = glCreateProgram();
    const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader), fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) throw std::runtime_error("render: shader program does not link");
    inverse_size = glGetUniformLocation(program, "inverse_size");

    glGenVertexArrays(1, &vao);
    glGenBuffers(1, &vbo);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
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

  void ensure_targets(ImageSize size, int samples) {
    if (size == target_size) return;
    glDeleteFramebuffers(1, &msaa_fbo);
    glDeleteFramebuffers(1, &resolve_fbo);
    glDeleteRenderbuffers(1, &msaa_rb);
    glDeleteRenderbuffers(1, &resolve_rb);
    msaa_fbo = msaa_rb = 0;
    glGenFramebuffers(1, &resolve_fbo);
    glGenRenderbuffers(1, &resolve_rb);
    attach(resolve_fbo, resolve_rb, 0, size);
    if (samples > 0) {
      glGenFramebuffers(1, &msaa_fbo);
      glGenRenderbuffers(1, &msaa_rb);
      attach(msaa_fbo, msaa_rb, samples, size);
    }
    target_size = size;
  }

  void draw(std::span<const Vertex> vertices, ImageSize size, int samples, std::span<std::uint8_t> rgba) {
    ensure_targets(size, samples);
    glBindFramebuffer(GL_FRAMEBUFFER, samples > 0 ? msaa_fbo : resolve_fbo);
    glViewport(0, 0, size.width, size.height);
    const Rgba bg = palette::kBackground;
    glClearColor(bg.r / 255.0f, bg.g / 255.0f, bg.b / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(program);
    glUniform2f(inverse_size, 1.0f / size.width, 1.0f / size.height);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size_bytes()), vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    if (samples > 0) {
      glBindFramebuffer(GL_READ_FRAMEBUFFER, msaa_fbo);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo);
      glBlitFramebuffer(0, 0, size.width, size.height, 0, 0, size.width, size.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, resolve_fbo);
    glReadPixels(0, 0, size.width, size.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
      throw std::runtime_error("render: GL error " + std::to_string(e));
    }
  }
};

OsmesaRasterizer::OsmesaRasterizer(int msaa_samples) : msaa_samples_(msaa_samples) {}

OsmesaRasterizer::~OsmesaRasterizer() = default;

bool OsmesaRasterizer::has_context() const { return gl_ != nullptr; }

void OsmesaRasterizer::rasterize(std::span<const Vertex> vertices, ImageSize size, std::span<std::uint8_t> rgba) {
  if (!is_rgba_of(size, rgba.size())) {
    throw std::invalid_argument("render: the pixel buffer does not match the image size");
  }
  if (!gl_) {
    // A half-made context is never kept: the next frame tries again from scratch.
    auto gl = std::make_unique<Gl>();
    gl->create_context();
    gl_ = std::move(gl);
  }
  gl_->draw(vertices, size, msaa_samples_, rgba);
}

}  // namespace softtune::render
