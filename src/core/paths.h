#pragma once
#include <filesystem>

namespace bz {

// The project root that holds shaders/, data/ and levels/. BEAMZONE_ROOT in the environment
// wins; otherwise the source tree the binary was built from.
std::filesystem::path project_root();
std::filesystem::path shaders_dir();
std::filesystem::path data_dir();
std::filesystem::path levels_dir();

}  // namespace bz
