#include "gl_context.h"

#include <cstdlib>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GL_GLEXT_PROTOTYPES 1
#include <GL/glcorearb.h>
#include <fmt/core.h>

namespace zb::oracle {
namespace {

[[noreturn]] void egl_fail(const char* call) {
  throw GlUnavailable(fmt::format("EGL: {} failed (error 0x{:04x}); the oracle needs Debian's "
                                  "libegl-mesa0 and libgl1-mesa-dri",
                                  call, static_cast<unsigned>(eglGetError())));
}

std::string gl_string(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return s ? s : "";
}

}  // namespace

void check_gl(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR)
    throw GlUnavailable(fmt::format("OpenGL: {}: error 0x{:04x}", what, static_cast<unsigned>(e)));
}

GlContext::GlContext(int width, int height) : width_(width), height_(height) {
  try {
    init();
  } catch (...) {
    release();
    throw;
  }
}

void GlContext::init() {
  // llvmpipe, whatever GPU the machine may have: the oracle is one fixed implementation.
  setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
  setenv("GALLIUM_DRIVER", "llvmpipe", 1);

  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!get_display) egl_fail("eglGetProcAddress(eglGetPlatformDisplayEXT)");
  EGLDisplay dpy = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (dpy == EGL_NO_DISPLAY) egl_fail("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
  EGLint major = 0, minor = 0;
  if (!eglInitialize(dpy, &major, &minor)) egl_fail("eglInitialize");
  display_ = dpy;
  if (!eglBindAPI(EGL_OPENGL_API)) egl_fail("eglBindAPI(EGL_OPENGL_API)");

  const EGLint attrs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                          EGL_NONE};
  // No config and no surface (EGL_KHR_no_config_context, EGL_KHR_surfaceless_context): the
  // frame lives in the FBO below.
  EGLContext ctx = eglCreateContext(dpy, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attrs);
  if (ctx == EGL_NO_CONTEXT) egl_fail("eglCreateContext(OpenGL 3.3 core)");
  context_ = ctx;
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) egl_fail("eglMakeCurrent");

  renderer_ = gl_string(GL_RENDERER);
  version_ = gl_string(GL_VERSION);
  if (renderer_.find("llvmpipe") == std::string::npos)
    throw GlUnavailable(fmt::format("OpenGL renderer is '{}', not llvmpipe", renderer_));

  GLint max_rb = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_rb);
  if (width_ > max_rb || height_ > max_rb)
    throw GlUnavailable(fmt::format("{}x{} exceeds GL_MAX_RENDERBUFFER_SIZE {}", width_, height_,
                                    max_rb));
  glGenRenderbuffers(1, &color_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, color_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  glGenRenderbuffers(1, &depth_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_rb_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw GlUnavailable("OpenGL: the RGBA8 + DEPTH_COMPONENT24 framebuffer is incomplete");
  GLint depth_bits = 0;
  glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                        GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depth_bits);
  if (depth_bits != 24)
    throw GlUnavailable(fmt::format("OpenGL: depth attachment has {} bits, not 24", depth_bits));
  glViewport(0, 0, width_, height_);
  check_gl("framebuffer set-up");
}

GlContext::~GlContext() { release(); }

void GlContext::release() {
  auto dpy = static_cast<EGLDisplay>(display_);
  if (context_) {
    glDeleteFramebuffers(1, &fbo_);
    glDeleteRenderbuffers(1, &color_rb_);
    glDeleteRenderbuffers(1, &depth_rb_);
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, static_cast<EGLContext>(context_));
    context_ = nullptr;
  }
  // No eglTerminate: Mesa unloads its driver there and leaves 240 bytes that LeakSanitizer
  // reports from an unknown module. The display is the process's and goes with it.
  display_ = nullptr;
}

}  // namespace zb::oracle
