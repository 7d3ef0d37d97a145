#pragma once
// Test-side expectations for line masks: project 3D segments exactly (double), clip them at
// the near plane, and mark the pixels each crosses with the same rule the mask shader uses.
// Then compare two masks with a pixel tolerance.
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "scene/frame_list.h"

namespace bz::test {

struct Mask {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> pixels;  // row 0 = top
    bool lit(int x, int y) const {
        return x >= 0 && y >= 0 && x < width && y < height &&
               pixels[static_cast<std::size_t>(y * width + x)];
    }
    int count() const;
};

Mask expected_mask(const scene::Camera& camera, int width, int height,
                   const std::vector<std::pair<glm::dvec3, glm::dvec3>>& segments);

struct MaskScore {
    double precision = 0.0;  // lit pixels of `test` within tol of a lit pixel of `ref`
    double recall = 0.0;     // lit pixels of `ref` within tol of a lit pixel of `test`
    int test_count = 0;
    int ref_count = 0;
};
MaskScore score_masks(const Mask& test, const Mask& ref, int tolerance_px);

}  // namespace bz::test
