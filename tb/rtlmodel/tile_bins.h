// Binning a pass's fragments by tile, stably: the order the RTL driver streams them in
// (tb/rtlmodel/tile_driver.cpp), shared with the SystemC modules (tb/systemc/).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rop/fragment.h"

namespace zb {

struct TileBins {
  int columns = 0;               // tiles per row
  std::vector<uint32_t> first;   // per tile, its start in `order`; one extra entry at the end
  std::vector<uint32_t> order;   // fragment indices, tile by tile, pass order within a tile
};

// Bins `n` fragments of a width x height frame into tiles of tile_w x tile_h pixels, each a
// power of two (std::invalid_argument otherwise).
void bin_by_tile(const Fragment* f, size_t n, int width, int height, int tile_w, int tile_h,
                 TileBins& out);

// A fragment as the RTL driver streams it: the fields zb_rop's fragment port takes (rgba
// pack_rgba) and its index in the pass.
struct Streamed {
  uint16_t x, y;
  uint32_t z, rgba, index;
  uint8_t cov;
};
// The pass's fragments binned into kRtlTileW x kRtlTileH tiles: `first` as TileBins::first,
// `out` the fragments in tile order.
void stream_by_tile(const Fragment* f, size_t n, int width, int height,
                    std::vector<uint32_t>& first, std::vector<Streamed>& out);

}  // namespace zb
