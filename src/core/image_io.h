#pragma once
// PNG in and out through stb. Row 0 is the top of the image, as PNG stores it.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace bz {

struct Image {
    int width = 0;
    int height = 0;
    int channels = 0;  // 1 (gray) or 4 (RGBA)
    std::vector<std::uint8_t> pixels;
    std::uint8_t at(int x, int y, int c = 0) const {
        return pixels[static_cast<std::size_t>((y * width + x) * channels + c)];
    }
};

// Written atomically; throws UserError on failure.
void write_png(const std::filesystem::path& path, const Image& image);
// Reads any PNG, converted to `channels` (1 or 4). Throws UserError naming the file.
Image read_png(const std::filesystem::path& path, int channels);

}  // namespace bz
