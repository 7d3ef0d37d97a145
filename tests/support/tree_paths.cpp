#include "support/tree_paths.h"

namespace bz::test {

std::filesystem::path source_dir() {
    return BEAMZONE_SOURCE_DIR;
}
std::filesystem::path binary_dir() {
    return BEAMZONE_BINARY_DIR;
}

}  // namespace bz::test
