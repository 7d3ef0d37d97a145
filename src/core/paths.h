#pragma once
#include <filesystem>
#include <string>

namespace bz {

// The folder that holds shaders/, data/ and levels/. The first of these that applies:
//   1. an installed binary: `../share/beamzone` next to the executable's own folder
//      (`cmake --install build --prefix P` puts P/bin/beamzone and P/share/beamzone/), used
//      when it holds shaders/; the install can be moved as a whole;
//   2. BEAMZONE_ROOT in the environment;
//   3. a binary still in its build tree: the source tree it was built from.
// When none applies, the installed location, so messages name where the data should be.
std::filesystem::path project_root();
std::filesystem::path shaders_dir();
std::filesystem::path data_dir();
std::filesystem::path levels_dir();

// Which rule chose project_root(), for the log: "installed", "BEAMZONE_ROOT", "source tree"
// or "missing".
std::string project_root_origin();

}  // namespace bz
