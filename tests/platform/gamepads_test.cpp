#include "platform/gamepads.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include "core/log.h"
#include "core/paths.h"

namespace bz::platform {
namespace {

namespace fs = std::filesystem;

TEST(Gamepads, BundledDatabaseLoadsAndUserFileOverrides) {
    const fs::path user =
        fs::temp_directory_path() / ("bz_pads_" + std::to_string(::getpid()) + ".txt");
    // One made-up Linux pad in SDL's mapping format.
    std::ofstream(user) << "030000000000000000000000beef0000,beamzone test pad,a:b0,b:b1,"
                           "leftx:a0,lefty:a1,platform:Linux,\n";
    Log log;
    Gamepads pads(log, data_dir() / "gamecontrollerdb" / "gamecontrollerdb.txt", user);
    // SDL counts only the lines for this platform; the bundled file has a few hundred.
    EXPECT_GT(pads.mappings_loaded(), 100);
    EXPECT_EQ(pads.count(), 0u);  // no pad on a test machine
    fs::remove(user);
}

TEST(Gamepads, MissingOrBadFilesAreNotFatal) {
    std::string why;
    EXPECT_LT(add_controller_mappings("/nonexistent/gamecontrollerdb.txt", &why), 0);
    EXPECT_FALSE(why.empty());
    Log log;
    Gamepads pads(log, "/nonexistent/a.txt", "/nonexistent/b.txt");
    EXPECT_EQ(pads.mappings_loaded(), 0);
}

}  // namespace
}  // namespace bz::platform
