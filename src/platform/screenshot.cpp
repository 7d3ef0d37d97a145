#include "platform/screenshot.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "core/image_io.h"

namespace bz::platform {

namespace {

constexpr std::string_view kPrefix = "screenshot-";
constexpr std::string_view kSuffix = ".png";

// The number in "screenshot-0042.png", or -1 for any other name.
long number_of(const std::string& name) {
    if (name.size() <= kPrefix.size() + kSuffix.size() || !name.starts_with(kPrefix) ||
        !name.ends_with(kSuffix)) {
        return -1;
    }
    const char* first = name.data() + kPrefix.size();
    const char* last = name.data() + name.size() - kSuffix.size();
    long n = -1;
    const auto [end, ec] = std::from_chars(first, last, n);
    return ec == std::errc() && end == last ? n : -1;
}

}  // namespace

std::filesystem::path next_screenshot_path(const std::filesystem::path& dir) {
    long highest = 0;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        highest = std::max(highest, number_of(it->path().filename().string()));
    }
    char name[48];
    std::snprintf(name, sizeof name, "screenshot-%04ld.png", highest + 1);
    return dir / name;
}

std::filesystem::path save_screenshot(const std::filesystem::path& dir, int width, int height,
                                      std::vector<std::uint8_t> rgba) {
    if (width <= 0 || height <= 0 ||
        rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
        throw UserError("screenshot: pixel buffer does not match " + std::to_string(width) + "x" +
                        std::to_string(height));
    }
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw UserError("cannot create " + dir.string() + ": " + ec.message());
    Image image;
    image.width = width;
    image.height = height;
    image.channels = 4;
    image.pixels = std::move(rgba);
    const auto path = next_screenshot_path(dir);
    write_png(path, image);
    return path;
}

}  // namespace bz::platform
