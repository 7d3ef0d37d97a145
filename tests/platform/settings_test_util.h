#pragma once
// The names the settings tests accept, and a parse of settings text with them: one copy for the
// platform tests (which share a unity batch under BEAMZONE_UNITY).
#include <string>
#include <vector>

#include "platform/settings.h"

namespace bz::platform::test {

inline const std::vector<std::string> kPresets = {"fast", "balanced", "high"};
// The style table's names (scene::accepted_style_names(); platform's tests do not link scene).
inline const std::vector<std::string> kStyles = {"vector",  "vector-xray", "toon",     "sketch",
                                                 "pop-art", "halo",        "occluded", "arcade"};

inline SettingsLoad parse(const std::string& text) {
    return parse_settings(text, "settings.toml", {kPresets, kStyles});
}

}  // namespace bz::platform::test
