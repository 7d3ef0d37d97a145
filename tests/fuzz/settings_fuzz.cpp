// libFuzzer target: any bytes through the settings reader give settings within their ranges
// and at most 100 positioned, printable messages; never a crash (deep keys once overflowed
// toml++'s stack), a sanitizer report or a hang.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_checks.h"
#include "platform/settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    static const std::string presets[] = {"fast", "balanced", "high"};
    // The style names of scene/style.h, old ones included (this target does not link scene).
    static const std::string styles[] = {"vector",  "vector-xray", "toon",     "sketch",
                                         "pop-art", "halo",        "occluded", "arcade"};
    const bz::platform::SettingsLoad r =
        bz::platform::parse_settings(text, "settings.toml", {presets, styles});
    if (r.errors.size() > 100) __builtin_trap();
    for (const std::string& e : r.errors) bz::fuzz::check_message(e, "settings.toml", false);
    const auto& s = r.settings;
    if (!(s.volume >= 0.0f && s.volume <= 1.0f)) __builtin_trap();
    bool known_style = false;
    for (const std::string& name : styles) known_style = known_style || s.style == name;
    if (!known_style) __builtin_trap();
    // A file that loaded cleanly is written back in a form that loads to the same settings.
    if (r.errors.empty()) {
        const auto again = bz::platform::parse_settings(bz::platform::format_settings(s),
                                                        "again.toml", {presets, styles});
        if (!again.errors.empty() || again.settings.keys != s.keys ||
            again.settings.preset != s.preset) {
            __builtin_trap();
        }
    }
    return 0;
}
