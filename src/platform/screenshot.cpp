#include "platform/screenshot.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <set>
#include <string>

#include "core/error.h"
#include "core/image_io.h"

namespace bz::platform {

namespace {

constexpr std::string_view kPrefix = "screenshot-";
// Numbers past this (a file someone named screenshot-99999999999999999999.png) are not
// continued from: counting on from them would overflow and reuse one name forever.
constexpr long kMaxNumber = 99'999'999;

// The number in "screenshot-0042.png" (kSuffix ".png"), or -1 for any other name.
long number_of(const std::string& name, std::string_view kSuffix) {
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

std::filesystem::path next_screenshot_path(const std::filesystem::path& dir,
                                           std::string_view extension) {
    std::set<long> used;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const long n = number_of(it->path().filename().string(), extension);
        if (n >= 1 && n <= kMaxNumber) used.insert(n);
    }
    auto path_for = [&](long n) {
        char name[48];
        std::snprintf(name, sizeof name, "screenshot-%04ld", n);
        return dir / (std::string(name) + std::string(extension));
    };
    // One past the highest, as long as that fits; else the lowest free number.
    long next = used.empty() ? 1 : *used.rbegin() + 1;
    if (next > kMaxNumber) {
        next = 1;
        for (const long n : used) {
            if (n != next) break;
            ++next;
        }
    }
    // Never a name that is taken, whatever else is in the folder.
    while (next <= kMaxNumber && std::filesystem::exists(path_for(next), ec)) ++next;
    if (next > kMaxNumber) {
        throw UserError(dir.string() + ": no free screenshot number left (" +
                        std::to_string(kMaxNumber) + " shots); move some away");
    }
    return path_for(next);
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
