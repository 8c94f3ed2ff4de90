#include "gl_render.h"

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#include <fmt/core.h>

namespace zb::oracle {
namespace {

// Clip-space position in, flat colour through: GL sees exactly the golden model's vertex
// stage output.
constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec4 clip;
layout(location = 1) in vec4 color;
uniform float y_sign;
flat out vec4 v_color;
void main() {
  gl_Position = vec4(clip.x, y_sign * clip.y, clip.z, clip.w);
  v_color = color;
}
)";
constexpr const char* kFragmentShader = R"(#version 330 core
flat in vec4 v_color;
layout(location = 0) out vec4 frag;
void main() { frag = v_color; }
)";

struct Vertex {
  float clip[4];
  uint8_t color[4];  // unorm8, normalized by GL: c / 255 in the shader, c again at the write
};

GLuint compile(GLenum kind, const char* text) {
  const GLuint s = glCreateShader(kind);
  glShaderSource(s, 1, &text, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[1024] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    throw GlUnavailable(fmt::format("OpenGL: shader does not compile: {}", log));
  }
  return s;
}

GLuint link_program() {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) throw GlUnavailable("OpenGL: shader program does not link");
  return p;
}

bool drawn_by(const PassState& pass, const ClipTriangle& t) {
  switch (pass.filter) {
    case PrimFilter::kOpaque: return !t.transparent;
    case PrimFilter::kTransparent: return t.transparent;
    default: return true;
  }
}

// The pass's datapath and cull state as GL state (docs/oracle.md, "State").
void apply_state(const PassState& pass, WindowY window_y) {
  const RopState& r = pass.rop;
  if (pass.cull == Cull::kNone) {
    glDisable(GL_CULL_FACE);
  } else {
    // Front = counter-clockwise as the viewer sees it, in both models; the picture drawn
    // upside down turns it clockwise in GL's window.
    glEnable(GL_CULL_FACE);
    glFrontFace(window_y == WindowY::kUp ? GL_CCW : GL_CW);
    glCullFace(pass.cull == Cull::kFront ? GL_FRONT : GL_BACK);
  }
  // GL's disabled depth test also never writes depth: the datapath's depth_test = 0.
  if (r.depth_test) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER + static_cast<GLenum>(r.depth_func));
  } else {
    glDisable(GL_DEPTH_TEST);
  }
  glDepthMask(r.depth_write ? GL_TRUE : GL_FALSE);
  switch (r.blend) {
    case BlendMode::kReplace:
      glDisable(GL_BLEND);
      break;
    case BlendMode::kAlpha:
      glEnable(GL_BLEND);
      glBlendEquation(GL_FUNC_ADD);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);  // every channel, alpha too
      break;
    case BlendMode::kAdditive:
      glEnable(GL_BLEND);
      glBlendEquation(GL_FUNC_ADD);
      glBlendFunc(GL_SRC_ALPHA, GL_ONE);
      break;
    default:
      throw std::invalid_argument("unsupported blend");  // unsupported_reason() rules it out
  }
  glColorMask((r.color_mask & kMaskR) != 0, (r.color_mask & kMaskG) != 0,
              (r.color_mask & kMaskB) != 0, (r.color_mask & kMaskA) != 0);
}

}  // namespace

std::string unsupported_reason(const PassPlan& plan) {
  if (!plan.final_ops.empty()) return "frame operations after the last pass";
  for (const PassState& p : plan.passes) {
    const std::string where = fmt::format("pass '{}': ", p.name);
    if (p.filter == PrimFilter::kEdges) return where + "draws tessellation edges";
    if (p.facing != FacingFilter::kAll || p.zero_alpha_toward)
      return where + "uses the per-vertex facing flag";
    if (p.offset.any()) return where + "uses a depth offset";
    if (p.constant_color) return where + "draws a constant colour";
    if (!p.frame_ops.empty()) return where + "has frame operations";
    if (p.rop.peel_test) return where + "uses the peel test";
    if (p.rop.blend != BlendMode::kReplace && p.rop.blend != BlendMode::kAlpha &&
        p.rop.blend != BlendMode::kAdditive)
      return where + fmt::format("blend '{}' has no OpenGL equivalent", to_string(p.rop.blend));
  }
  return "";
}

GlRenderer::GlRenderer(GlContext& gl) : gl_(gl), program_(link_program()) {
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, clip)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                        reinterpret_cast<const void*>(offsetof(Vertex, color)));
  check_gl("vertex array setup");
}

GlRenderer::~GlRenderer() {
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
  glDeleteProgram(program_);
}

Framebuffer GlRenderer::draw(const std::vector<ClipTriangle>& triangles, const PassPlan& plan,
                             Rgba8 background, WindowY window_y) {
  if (const std::string why = unsupported_reason(plan); !why.empty())
    throw std::invalid_argument(fmt::format("method '{}': {}", plan.name, why));

  glBindVertexArray(vao_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glUseProgram(program_);
  // Negated clip y and GL's y-up viewport give window y = (1 - y_ndc) H / 2: zblend's formula.
  glUniform1f(glGetUniformLocation(program_, "y_sign"), window_y == WindowY::kDown ? -1.0f : 1.0f);

  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f,
               background.a / 255.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  std::vector<Vertex> vertices;
  vertices.reserve(3 * triangles.size());
  for (const PassState& pass : plan.passes) {
    vertices.clear();
    for (const ClipTriangle& t : triangles) {
      if (!drawn_by(pass, t)) continue;
      const Rgba8 c = t.color;
      for (const glm::vec4& p : t.clip) vertices.push_back({{p.x, p.y, p.z, p.w}, {c.r, c.g, c.b, c.a}});
    }
    apply_state(pass, window_y);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vertices.size()));
    check_gl(fmt::format("pass '{}'", pass.name).c_str());
  }

  // GL's row 0 is window y = 0: the top row of the picture under kDown, the bottom under kUp.
  const int w = gl_.width(), h = gl_.height();
  Framebuffer fb(w, h, 24, background);
  std::vector<Rgba8> rgba(static_cast<size_t>(w) * h);
  std::vector<uint32_t> depth(static_cast<size_t>(w) * h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  // A 24-bit depth read as GL_UNSIGNED_INT is scaled to 32 bits: the top 24 are the value.
  glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
  check_gl("glReadPixels");
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int row = window_y == WindowY::kDown ? y : h - 1 - y;
      const size_t src = static_cast<size_t>(row) * w + x;
      fb.color[fb.index(x, y)] = rgba[src];
      fb.depth[fb.index(x, y)] = depth[src] >> 8;
    }
  return fb;
}

Framebuffer render_gl(GlContext& gl, const std::vector<ClipTriangle>& triangles,
                      const PassPlan& plan, Rgba8 background, WindowY window_y) {
  if (const std::string why = unsupported_reason(plan); !why.empty())
    throw std::invalid_argument(fmt::format("method '{}': {}", plan.name, why));
  GlRenderer renderer(gl);
  return renderer.draw(triangles, plan, background, window_y);
}

}  // namespace zb::oracle
