#pragma once
// Pixels of a frame: N x N supersampled camera rays per pixel, averaged in
// linear RGB, plus the data layers of docs/layers.md from the ray through the
// pixel centre.  Rows are independent, so any split over threads or
// processes gives bit-identical images.

#include <atomic>
#include <span>

#include "image/image.hpp"
#include "render/hit_record.hpp"
#include "render/render_settings.hpp"

namespace lc {

class SampleMemo;
class Scene;  // render/scene.hpp

// Makes room in `image` (made by make_frame) for its rays' sky points when
// the scene's sky has stars drawn as points (FrameImage::sky, a plane per
// instant of a blurred frame's shutter; the star pass after the pixels
// reads them).  Not thread-safe: call it once for a frame
// before rendering its rows.
void prepare_frame(const Scene& scene, FrameImage& image);

// Renders the listed rows into `image` (made by make_frame, then
// prepare_frame for this scene).  Thread-safe for disjoint rows.  With a memo (made for the same settings), samples kept
// from earlier frames of the same still_key are taken instead of traced,
// and this frame's timeless ones kept: the image is the same either way.
RenderStats render_rows(const Scene& scene, const RenderSettings& rs, std::span<const int> rows, FrameImage& image,
                        SampleMemo* memo = nullptr);

// Renders a whole frame with `threads` threads (0: every core), rows handed
// out dynamically.  `rows_done`, when given, counts finished rows (progress).
// The sample through image point (px, py) of the scene's camera, from the
// frame's eye, traced and shaded: what a test or a tool that looks at
// single pixels reads, without visiting every spacetime itself.
RaySample trace_image_point(const Scene& scene, double px, double py);

FrameImage render_frame(const Scene& scene, const RenderSettings& rs, int threads, RenderStats* stats = nullptr,
                        std::atomic<int>* rows_done = nullptr);

}  // namespace lc
