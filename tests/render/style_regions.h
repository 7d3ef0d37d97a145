#pragma once
// Regions of a rendered frame, found without the GPU, for the style tests: where the objects
// cover the screen (a CPU rasteriser of their triangles at pixel centres) and where the exact
// feature lines run (a mask), grown or shrunk by a radius; and small statistics of an RGBA8
// frame over such a region.
#include <cstdint>
#include <functional>
#include <vector>

#include "render/settings.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"

namespace bz::test {

// One flag per pixel, row 0 at the top (as PNGs and Renderer::read_color).
struct Region {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> on;
    bool at(int x, int y) const { return on[static_cast<std::size_t>(y) * width + x] != 0; }
    std::size_t count() const;
};

// Pixels whose centre some triangle of the frame's items covers.
Region coverage(const scene::FrameList& frame, const scene::MeshLibrary& meshes, int width,
                int height);
// From a 0/255 mask.
Region from_mask(const std::vector<std::uint8_t>& mask, int width, int height);
// Pixels with every pixel within `radius` (Chebyshev) on: shrinks the region.
Region eroded(const Region& r, int radius);
// Pixels with some pixel within `radius` on: grows the region.
Region dilated(const Region& r, int radius);
Region minus(const Region& a, const Region& b);
Region inverted(const Region& r);

struct Rgb {
    float r, g, b;  // 0..1, display-referred, as stored
    float luma() const { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }
};
Rgb pixel(const std::vector<std::uint8_t>& rgba, int width, int x, int y);
// The share of the region's pixels that pass `test` (0 for an empty region).
double share(const Region& region, const std::vector<std::uint8_t>& rgba,
             const std::function<bool(const Rgb&)>& test);
// The share of the region's pixels with a pixel passing `test` within `radius`.
double share_near(const Region& region, const std::vector<std::uint8_t>& rgba, int radius,
                  const std::function<bool(const Rgb&)>& test);

}  // namespace bz::test
