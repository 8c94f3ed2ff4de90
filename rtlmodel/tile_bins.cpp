#include "tile_bins.h"

namespace zb {

void bin_by_tile(const Fragment* f, size_t n, int width, int height, int tile_w, int tile_h,
                 TileBins& out) {
  const int tx = (width + tile_w - 1) / tile_w, ty = (height + tile_h - 1) / tile_h;
  out.columns = tx;
  out.first.assign(size_t(tx) * size_t(ty) + 1, 0);
  auto tile_of = [&](const Fragment& g) { return size_t(g.y / tile_h) * size_t(tx) + g.x / tile_w; };
  for (size_t i = 0; i < n; ++i) ++out.first[tile_of(f[i]) + 1];
  for (size_t i = 1; i < out.first.size(); ++i) out.first[i] += out.first[i - 1];
  out.order.resize(n);
  std::vector<uint32_t> pos(out.first.begin(), out.first.end() - 1);
  for (size_t i = 0; i < n; ++i) out.order[pos[tile_of(f[i])]++] = uint32_t(i);
}

}  // namespace zb
