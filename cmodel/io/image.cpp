#include "image.h"

#include <cstdlib>

#include <zlib.h>

namespace {

// stb's PNG writer with zlib's deflate instead of its own: several times faster at a smaller
// file (error maps doubled a render's time with stb's, docs/cli.md "Error maps").
unsigned char* zlib_compress(unsigned char* data, int size, int* out_size, int /*quality*/) {
  uLongf bound = compressBound(uLong(size));
  auto* out = static_cast<unsigned char*>(std::malloc(bound));
  if (out && compress2(out, &bound, data, uLong(size), Z_DEFAULT_COMPRESSION) == Z_OK) {
    *out_size = int(bound);
    return out;
  }
  std::free(out);
  return nullptr;
}

}  // namespace

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#define STBIW_ZLIB_COMPRESS zlib_compress
#include <stb_image_write.h>

namespace zb {

namespace {

// One PNG filter for every row (Paeth, the best on the frames and maps tried) instead of stb's
// trial of all five per row: the encoder's time mostly went there. Set before any thread runs.
const bool kPngFilterSet = [] {
  stbi_write_force_png_filter = 4;
  return true;
}();

}  // namespace


namespace {

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<size_t>(size));
}

}  // namespace

std::string write_png(const std::string& path, const Framebuffer& fb) {
  return write_png(path, fb.width, fb.height, fb.color.data());
}

std::string write_png(const std::string& path, int width, int height, const Rgba8* color) {
  const size_t n = size_t(width) * size_t(height);
  std::vector<uint8_t> rgb(n * 3);
  for (size_t i = 0; i < n; ++i) {
    rgb[3 * i] = color[i].r;
    rgb[3 * i + 1] = color[i].g;
    rgb[3 * i + 2] = color[i].b;
  }
  std::string png;
  if (!stbi_write_png_to_func(append, &png, width, height, 3, rgb.data(), width * 3))
    return "cannot encode PNG for '" + path + "'";
  return write_file_atomic(path, png);
}

}  // namespace zb
