// zb_rop's parameters as the C++ side sees them. CMake defines them from its cache options
// ZBLEND_RTL_* (the same values it gives Verilator as -G parameters) for every target that
// links zbrtl_common; rop_model.cpp static_asserts them against the Verilated model.
#pragma once

#if !defined(ZBLEND_RTL_DEPTH_BITS) || !defined(ZBLEND_RTL_COV_SAMPLES) || !defined(ZBLEND_RTL_TILE) || \
    !defined(ZBLEND_RTL_WINDOW) || !defined(ZBLEND_RTL_BEAT) || !defined(ZBLEND_RTL_ACC_BITS) || \
    !defined(ZBLEND_RTL_REV_BITS) || !defined(ZBLEND_RTL_WEIGHT_BITS) || !defined(ZBLEND_RTL_LAYERS) || \
    !defined(ZBLEND_VERILATOR_THREADS)
#error "ZBLEND_RTL_DEPTH_BITS, _COV_SAMPLES, _TILE, _WINDOW, _BEAT, _ACC_BITS, _REV_BITS, _WEIGHT_BITS, _LAYERS and ZBLEND_VERILATOR_THREADS come from CMake: link zbrtl_common"
#endif

#include "rop/fixed.h"

namespace zb {

constexpr int kRtlTileW = ZBLEND_RTL_TILE;
constexpr int kRtlTileH = ZBLEND_RTL_TILE;
constexpr int kRtlDepthBits = ZBLEND_RTL_DEPTH_BITS;
constexpr int kRtlCoverageSamples = ZBLEND_RTL_COV_SAMPLES;  // COV_SAMPLES
constexpr unsigned kRtlWindow = ZBLEND_RTL_WINDOW;           // WINDOW: issue window slots
constexpr int kRtlBeat = ZBLEND_RTL_BEAT;                    // BEAT: tile port pixels per clock
// ACC_BITS, REV_BITS, WEIGHT_BITS: the accumulate blend's widths (docs/datapath.md "7.").
constexpr WboitFormat kRtlWboit{ZBLEND_RTL_ACC_BITS, ZBLEND_RTL_REV_BITS, ZBLEND_RTL_WEIGHT_BITS};
// DEPTH_GEN: with the tile operations (every simulated build), copies of depth to peel are
// renamed and the depth banks' words carry a generation of this many bits (docs/rtl.md
// "Renamed copies").
constexpr int kRtlDepthGenBits = 2;
// LAYERS: mlab-K's layers a pixel (docs/datapath.md "8. Layers"), the largest K the model runs
// (the mutant netlist has no layers unit: RtlRop refuses layers passes there).
constexpr int kRtlLayers = ZBLEND_RTL_LAYERS;
constexpr unsigned kVerilatorThreads = ZBLEND_VERILATOR_THREADS;  // the model's --threads

}  // namespace zb
