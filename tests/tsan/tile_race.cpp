// An injected race for ThreadSanitizer to catch: two threads store the same tile of one frame,
// as tile-parallel models would if two were handed one tile, or if a store allocated planes
// (the race fixed by prepare_stores). Run with an argument "safe", the threads store
// neighbouring tiles, which must be clean: the catch is the overlap, not the threads.
#include <cstring>
#include <thread>

#include "tile_io.h"

int main(int argc, char** argv) {
  using namespace zb;
  const bool safe = argc > 1 && std::strcmp(argv[1], "safe") == 0;
  Framebuffer fb(2 * kRtlTileW, kRtlTileH, kRtlDepthBits, Rgba8{0, 0, 0, 255},
                 kRtlCoverageSamples, kRtlWboit);
  RopState accumulate;
  accumulate.blend = BlendMode::kAccumulate;
  prepare_stores(fb, accumulate);
  auto store = [&fb](int x0, uint32_t value) {
    const TileSweep sweep(fb.width, fb.height, x0, 0);
    BeatWords w{};
    for (auto& lane : w[0]) lane = value;
    for (int k = 0; k < sweep.beats(); ++k) sweep.store(w, kPlaneColor | kPlaneAccum, fb, k);
  };
  std::thread a(store, 0, 0x11223344u);
  std::thread b(store, safe ? kRtlTileW : 0, 0x55667788u);
  a.join();
  b.join();
  return 0;
}
