// libFuzzer target: any bytes through the level loader must give either a level or
// positioned errors, never a crash, a sanitizer report or a hang.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "level/loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    // Pretend the input sits in levels/ so the shipped seeds' model paths resolve for real.
    static const std::filesystem::path file =
        std::filesystem::path(BEAMZONE_SOURCE_DIR) / "levels" / "fuzz-input.toml";
    bz::level::LoadOptions options;
    options.data_root = std::filesystem::path(BEAMZONE_SOURCE_DIR) / "data";
    const bz::level::LoadResult result = bz::level::load_level_string(text, file, options);
    // The loader's contract, checked on every input.
    if (result.level.has_value() == !result.errors.empty()) __builtin_trap();
    for (const auto& e : result.errors) {
        const std::string line = bz::level::format(e);
        if (line.find('\n') != std::string::npos || e.message.empty()) __builtin_trap();
        if (e.pos.line < 1 || e.pos.column < 1) __builtin_trap();  // always file:line:col
    }
    return 0;
}
