#include "platform/pref_paths.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>

namespace bz::platform {
namespace {

namespace fs = std::filesystem;

TEST(PrefPaths, EnvironmentOverrideIsCreatedAndUsed) {
    const fs::path dir =
        fs::temp_directory_path() / ("bz_pref_" + std::to_string(::getpid())) / "nested";
    ::setenv("BEAMZONE_PREF_DIR", dir.c_str(), 1);
    const PrefPaths p = pref_paths();
    ::unsetenv("BEAMZONE_PREF_DIR");
    EXPECT_TRUE(fs::is_directory(dir));
    EXPECT_EQ(p.dir, dir);
    EXPECT_EQ(p.settings, dir / "settings.toml");
    EXPECT_EQ(p.high_scores.parent_path(), dir);
    EXPECT_EQ(p.log.parent_path(), dir);
    EXPECT_EQ(p.gamepad_db, dir / "gamecontrollerdb.txt");
    EXPECT_NE(p.settings, p.high_scores);
    fs::remove_all(dir.parent_path());
}

}  // namespace
}  // namespace bz::platform
