#include "render/beam/bloom_kernel.h"

#include <algorithm>
#include <cmath>

namespace bz::render {

BloomKernel bloom_kernel(int taps, float sigma) {
    taps = std::clamp(taps | 1, 3, 31);
    const int radius = taps / 2;
    sigma = std::max(sigma, 0.1f);
    std::vector<double> w(static_cast<std::size_t>(radius) + 1);
    double total = 0.0;
    for (int i = 0; i <= radius; ++i) {
        w[static_cast<std::size_t>(i)] =
            std::exp(-0.5 * i * i / (static_cast<double>(sigma) * sigma));
        total += (i == 0 ? 1.0 : 2.0) * w[static_cast<std::size_t>(i)];
    }
    for (auto& x : w) x /= total;
    BloomKernel k;
    k.offsets.push_back(0.0f);
    k.weights.push_back(static_cast<float>(w[0]));
    for (int i = 1; i <= radius; i += 2) {
        const double w1 = w[static_cast<std::size_t>(i)];
        const double w2 = i + 1 <= radius ? w[static_cast<std::size_t>(i + 1)] : 0.0;
        const double sum = w1 + w2;
        k.weights.push_back(static_cast<float>(sum));
        k.offsets.push_back(static_cast<float>((i * w1 + (i + 1) * w2) / sum));
    }
    return k;
}

}  // namespace bz::render
