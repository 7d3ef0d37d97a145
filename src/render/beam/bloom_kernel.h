#pragma once
// Gaussian weights folded into linear-sampling fetches (Rakos 2010): discrete taps 2i-1 and
// 2i share one bilinear fetch placed at their weighted centre.
#include <vector>

namespace bz::render {

struct BloomKernel {
    std::vector<float> offsets;  // [0] = 0 (centre), then one per side pair
    std::vector<float> weights;  // normalised: weights[0] + 2 * sum(rest) == 1
};

// `taps` discrete taps per direction (odd, >= 3; clamped to 31), Gaussian of `sigma` texels.
BloomKernel bloom_kernel(int taps, float sigma);

}  // namespace bz::render
