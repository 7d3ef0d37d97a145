// Only regular files are ever opened: a FIFO (which would block the reader forever), a device
// or a folder, as the model itself or as a file the model refers to, is refused at once.
#include <gtest/gtest.h>

#include <chrono>

#include "gltf_test_files.h"
#include "import_test_util.h"

namespace bz::geo {
namespace {

using namespace test;  // ScratchDir, import_error, expect_refusal, quick, seconds_since

TEST(SpecialFiles, FifoAsTheModelIsRefusedWithoutBlocking) {
    ScratchDir dir;
    const auto p = make_fifo(dir, "model.obj");
    const auto start = Clock::now();
    expect_refusal(import_error(p, quick()), p, "not a regular file (a FIFO)");
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(SpecialFiles, FifoAsMtllibIsRefused) {
    ScratchDir dir;
    make_fifo(dir, "materials.mtl");
    const auto p =
        dir.write("model.obj", "mtllib materials.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const auto start = Clock::now();
    const std::string m = import_error(p, quick());
    expect_refusal(m, p, "reference '");
    EXPECT_NE(m.find("materials.mtl': not a regular file (a FIFO)"), std::string::npos) << m;
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(SpecialFiles, FifoAsGltfBufferUriIsRefused) {
    ScratchDir dir;
    make_fifo(dir, "tri.bin");
    const auto p = dir.write(
        "model.gltf",
        test::gltf_json(R"({"uri": "tri.bin", "byteLength": 42})", R"([{"mesh": 0}])", "[0]"));
    const auto start = Clock::now();
    const std::string m = import_error(p, quick());
    expect_refusal(m, p, "tri.bin': not a regular file (a FIFO)");
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
