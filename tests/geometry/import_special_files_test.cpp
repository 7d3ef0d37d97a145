// Only regular files are ever opened: a FIFO (which would block the reader forever), a device
// or a folder as the model is refused at once.
#include <gtest/gtest.h>

#include <chrono>

#include "import_test_util.h"

namespace bz::geo {
namespace {

using Clock = std::chrono::steady_clock;
using test::expect_refusal;
using test::import_error;
using test::quick;
using test::ScratchDir;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

TEST(SpecialFiles, FifoAsTheModelIsRefusedWithoutBlocking) {
    ScratchDir dir;
    const auto p = dir.fifo("model.obj");
    const auto start = Clock::now();
    expect_refusal(import_error(p, quick()), p, "not a regular file (a FIFO)");
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(SpecialFiles, SymlinkToADeviceIsRefused) {
    ScratchDir dir;
    std::filesystem::create_symlink("/dev/zero", dir.path() / "zero.obj");
    const auto p = dir.path() / "zero.obj";
    ImportOptions o = quick();
    o.allowed_folders = {"/"};  // confinement aside: the kind of file alone refuses it
    expect_refusal(import_error(p, o), p, "not a regular file (a character device)");
}

TEST(SpecialFiles, FolderNamedLikeAModelIsRefused) {
    ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "folder.obj");
    expect_refusal(import_error(dir.path() / "folder.obj", quick()), dir.path() / "folder.obj",
                   "not a regular file (a folder)");
}

}  // namespace
}  // namespace bz::geo
