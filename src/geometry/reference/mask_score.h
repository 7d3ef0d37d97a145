#pragma once
// Scores a line mask against a reference mask with a pixel tolerance: precision, recall, F1.
#include <cstddef>
#include <cstdint>
#include <span>

namespace bz::geo {

struct MaskScore {
    double precision = 1.0;  // lit test pixels with a lit reference pixel within the tolerance
    double recall = 1.0;     // lit reference pixels with a lit test pixel within the tolerance
    double f1 = 1.0;         // 2PR / (P + R); 0 when both are 0
    std::size_t test_lit = 0;
    std::size_t ref_lit = 0;
};

// Both masks are width * height bytes (non-zero = lit). "Within the tolerance" is the
// (2 tol + 1)^2 square around a pixel (Chebyshev distance <= tol). An empty mask counts as
// fully precise (nothing wrong was drawn) and as fully recalled only if the other is empty too.
// Throws std::invalid_argument when the sizes do not match or tol < 0.
MaskScore score_masks(std::span<const std::uint8_t> test, std::span<const std::uint8_t> ref,
                      int width, int height, int tolerance_px);

}  // namespace bz::geo
