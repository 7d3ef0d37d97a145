#pragma once
// The source and build trees this test binary was configured with. Only tree_paths.cpp sees
// the absolute paths, so every other test object compiles the same in any checkout and ccache
// can share it between worktrees.
#include <filesystem>

namespace bz::test {

std::filesystem::path source_dir();
std::filesystem::path binary_dir();

}  // namespace bz::test
