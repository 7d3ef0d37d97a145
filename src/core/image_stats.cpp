#include "core/image_stats.h"

#include <algorithm>
#include <cstddef>

namespace bz {

double lit_share(const Image& image, int level) {
    const std::size_t count =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    if (count == 0 || image.channels <= 0) return 0.0;
    const int colour_channels = image.channels == 4 ? 3 : image.channels;
    std::size_t lit = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint8_t* p = image.pixels.data() + i * static_cast<std::size_t>(image.channels);
        const int peak = *std::max_element(p, p + colour_channels);
        lit += peak > level ? 1 : 0;
    }
    return static_cast<double>(lit) / static_cast<double>(count);
}

}  // namespace bz
