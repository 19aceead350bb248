// cpu_renderer.h: the CPU backend. Runs a Frame through the C++ twins on the
// tile-based rasterizer and returns a bit-stable float image.
//
// Per pass: vertex stage (twins, in parallel over vertex ranges) ->
// primitive assembly, near/far clipping, setup and binning into 64x64 tiles
// (in draw order) -> per tile, in parallel: for each binned triangle in
// order, rasterize its quads, shade them, depth-test and blend. A tile is
// only ever touched by one worker and sees triangles in submission order, so
// the image cannot depend on the thread count.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "frame/frame.h"
#include "image/image.h"
#include "raster/stage_times.h"

namespace st {

class TwinLibrary;

// A frame the renderer cannot draw as llvmpipe would, through no fault of
// its own (a vertex the vertex twin put at clip w ~ 0): a refusal of the
// input, found only once the vertex stage has run.
struct UnrenderableInput : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class CpuRenderer {
public:
    // `twins` resolves the program names of each draw; it must outlive the
    // renderer (kernels/registry.h has the built-in one).
    CpuRenderer(int threads, const TwinLibrary& twins);
    ~CpuRenderer();

    // Resolves twins and builds samplers. Throws std::runtime_error naming
    // the program or uniform that is missing.
    void prepare(const Frame& frame);
    // Renders every pass; stage_times() then holds this frame's breakdown.
    void execute();
    // The frame's image (the last pass without a named target).
    Image read_back() const;
    // One level of a named render target as the frame left it.
    Image read_back(const std::string& target, int level) const;

    Image render(const Frame& frame) {
        prepare(frame);
        execute();
        return read_back();
    }

    const StageTimes& stage_times() const { return times_; }
    int threads() const;

private:
    struct Impl;
    const TwinLibrary& twins_;
    std::unique_ptr<Impl> impl_;
    StageTimes times_;
};

}  // namespace st
