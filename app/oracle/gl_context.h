// An off-screen OpenGL context on Mesa's llvmpipe: EGL on the surfaceless platform, a core
// context with no surface, and a framebuffer object of RGBA8 colour and 24-bit depth.
#pragma once

#include <stdexcept>
#include <string>

namespace zb::oracle {

// OpenGL or EGL is missing or refused something: the oracle cannot run on this machine.
struct GlUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class GlContext {
 public:
  // Makes the context current with a width x height FBO bound. Throws GlUnavailable, naming
  // the call that failed, or when the renderer is not llvmpipe.
  GlContext(int width, int height);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  const std::string& renderer() const { return renderer_; }  // GL_RENDERER
  const std::string& version() const { return version_; }    // GL_VERSION

 private:
  void init();
  void release();

  int width_;
  int height_;
  std::string renderer_;
  std::string version_;
  void* display_ = nullptr;
  void* context_ = nullptr;
  unsigned fbo_ = 0;
  unsigned color_rb_ = 0;
  unsigned depth_rb_ = 0;
};

// Throws GlUnavailable naming `what` when glGetError reports an error.
void check_gl(const char* what);

}  // namespace zb::oracle
