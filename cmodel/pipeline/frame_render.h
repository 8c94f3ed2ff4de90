// A whole frame on the golden model, fast: the screen cut into bands of rows, each band
// rasterized and drawn through its own GoldenRop by a pool of threads, fragments streamed
// through a small buffer instead of stored for the whole frame. Bit for bit the framebuffer
// and per-pass statistics of render(rasterize_scene(scene, vp), plan, GoldenRop)
// (docs/raster.md, "Banded rendering").
#pragma once

#include <vector>

#include "geometry/frame_geometry.h"
#include "passes.h"
#include "render.h"
#include "scene/scene.h"

namespace zb {

// Rows per band: small enough that a band's planes (13 bytes a pixel) stay in the cache while
// every pass runs over it, large enough that few triangles straddle bands; 32 to 128 measured
// alike on bunny.obj at 1024x1024, and smaller bands hold less memory per thread.
constexpr int kDefaultBandRows = 32;

struct FrameRenderOptions {
  int threads = 0;    // workers, the caller included; 0 = std::thread::hardware_concurrency()
  int band_rows = 0;  // 0 = kDefaultBandRows
  // render_frame(scene, ...): split setup_triangles over the threads too. Faster (bunny.obj,
  // 2 cores: 7.5 ms serial, 4.7 ms split), but each thread holds its part's vertices, clipped
  // and set-up triangles at once: megabytes more at the peak (docs/raster.md).
  bool parallel_setup = false;
};

// The frame and per-pass statistics of `plan` drawn over `geometry` on the golden model,
// exactly as render() gives them. Throws std::invalid_argument as GoldenRop does (a coverage
// sample count that is not 1, 2, 4, 8 or 16) and for a viewport outside 1..kMaxFrameSize.
RenderResult render_frame(const FrameGeometry& geometry, const PassPlan& plan,
                          const FrameRenderOptions& options = {});

// make_frame_geometry (edges only when the plan draws them; on options.threads threads with
// options.parallel_setup, else serially), then render_frame.
RenderResult render_frame(const Scene& scene, const Viewport& vp, const PassPlan& plan,
                          const FrameRenderOptions& options = {});

}  // namespace zb
