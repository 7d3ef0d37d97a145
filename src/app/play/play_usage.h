#pragma once
// The `beamzone play --help` text: options (cli/play_args.h), keys and the player's files.
#include <string>

namespace bz::app {

// The --help text, with the user's settings and high-score files named.
std::string play_usage(const std::string& settings_path, const std::string& high_scores_path);

}  // namespace bz::app
