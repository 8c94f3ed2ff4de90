#include "image.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

namespace zb {

std::string write_file_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) return "cannot write '" + path + "': " + std::strerror(errno);
  const bool wrote = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  const int err = errno;
  if (std::fclose(f) != 0 || !wrote) {
    std::remove(tmp.c_str());
    return "cannot write '" + path + "': " + std::strerror(wrote ? errno : err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    return "cannot write '" + path + "': " + why;
  }
  return {};
}

namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<size_t>(size));
}

}  // namespace

std::string write_png(const std::string& path, const Framebuffer& fb) {
  std::vector<uint8_t> rgb(fb.color.size() * 3);
  for (size_t i = 0; i < fb.color.size(); ++i) {
    rgb[3 * i] = fb.color[i].r;
    rgb[3 * i + 1] = fb.color[i].g;
    rgb[3 * i + 2] = fb.color[i].b;
  }
  std::string png;
  if (!stbi_write_png_to_func(append, &png, fb.width, fb.height, 3, rgb.data(), fb.width * 3))
    return "cannot encode PNG for '" + path + "'";
  return write_file_atomic(path, png);
}

}  // namespace zb
