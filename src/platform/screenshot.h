#pragma once
// Numbered screenshots: screenshot-0001.png, screenshot-0002.png, ... in one folder.
#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

namespace bz::platform {

// The next free name: one past the highest number already there, so deleting an old shot
// never makes a new one reuse its number. Each extension (".png", ".svg": no more than a few
// characters) counts on its own.
std::filesystem::path next_screenshot_path(const std::filesystem::path& dir,
                                           std::string_view extension = ".png");

// Writes RGBA8 pixels (row 0 at the top) as the next numbered PNG, creating `dir` if needed.
// Returns the path written; throws UserError on failure.
std::filesystem::path save_screenshot(const std::filesystem::path& dir, int width, int height,
                                      std::vector<std::uint8_t> rgba);

}  // namespace bz::platform
