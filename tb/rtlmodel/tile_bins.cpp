#include "tile_bins.h"

#include <stdexcept>
#include <utility>

#include "rtl_params.h"
#include "tile_io.h"

namespace zb {

void bin_by_tile(const Fragment* f, size_t n, int width, int height, int tile_w, int tile_h,
                 TileBins& out) {
  // Tiles are powers of two (zb_rop's TILE_W, TILE_H): a shift, not a division, per fragment.
  auto log2_of = [](int v) {
    if (v < 1 || (v & (v - 1)) != 0)
      throw std::invalid_argument("bin_by_tile: a tile side must be a power of two");
    int s = 0;
    while ((1 << s) < v) ++s;
    return s;
  };
  const int sx = log2_of(tile_w), sy = log2_of(tile_h);
  const int tx = (width + tile_w - 1) >> sx, ty = (height + tile_h - 1) >> sy;
  out.columns = tx;
  out.first.assign(size_t(tx) * size_t(ty) + 1, 0);
  auto tile_of = [&](const Fragment& g) {
    return size_t(g.y >> sy) * size_t(tx) + size_t(g.x >> sx);
  };
  for (size_t i = 0; i < n; ++i) ++out.first[tile_of(f[i]) + 1];
  for (size_t i = 1; i < out.first.size(); ++i) out.first[i] += out.first[i - 1];
  out.order.resize(n);
  std::vector<uint32_t> pos(out.first.begin(), out.first.end() - 1);
  for (size_t i = 0; i < n; ++i) out.order[pos[tile_of(f[i])]++] = uint32_t(i);
}

void stream_by_tile(const Fragment* f, size_t n, int width, int height,
                    std::vector<uint32_t>& first, std::vector<Streamed>& out) {
  TileBins bins;
  bin_by_tile(f, n, width, height, kRtlTileW, kRtlTileH, bins);
  first = std::move(bins.first);
  out.resize(n);
  for (size_t k = 0; k < bins.order.size(); ++k) {
    const Fragment& g = f[bins.order[k]];
    out[k] = Streamed{g.x, g.y, g.z, pack_rgba(g.color), bins.order[k], g.coverage};
  }
}

}  // namespace zb
