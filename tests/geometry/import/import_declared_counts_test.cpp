// Files whose headers declare more elements than they hold (PLY ascii and binary, OFF, binary
// STL) and text files with too many lines (OBJ) are refused before Assimp allocates for them.
#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <fstream>

#include "geometry/import/import_guard.h"
#include "import_test_util.h"

namespace bz::geo {
namespace {

using namespace test;  // ScratchDir, import_error, expect_refusal, quick, seconds_since

TEST(DeclaredCounts, PlyAsciiDeclaringBillionsOfVerticesIsRefusedAtOnce) {
    ScratchDir dir;
    // The 190-byte shape of the file that grew the game to 17.6 GB.
    const auto p =
        dir.write("huge.ply",
                  "ply\nformat ascii 1.0\nelement vertex 1500000000\nproperty float x\n"
                  "property float y\nproperty float z\nelement face 1\n"
                  "property list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 0\n");
    const auto start = Clock::now();
    expect_refusal(import_error(p, quick()), p, "PLY header declares 1500000000 'vertex' elements");
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(DeclaredCounts, PlyBinaryHeaderIsBoundedByItsPropertySizes) {
    ScratchDir dir;
    std::string body(1200, '\0');  // room for 100 float3 vertices
    const std::string header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4000000\nproperty float x\n"
        "property float y\nproperty float z\nend_header\n";
    const auto p = dir.write("many.ply", header + body);
    expect_refusal(import_error(p, quick()), p, "PLY header declares 4000000 'vertex' elements");
    // 48 MB declared in 1.2 KB: a double-precision vertex costs 24 bytes, not 12.
    const auto d = dir.write("doubles.ply",
                             "ply\nformat binary_little_endian 1.0\nelement vertex 2000000\n"
                             "property double x\nproperty double y\nproperty double z\n"
                             "end_header\n" +
                                 body);
    expect_refusal(import_error(d, quick()), d, "PLY header declares 2000000 'vertex' elements");
    // Elements without properties still cost memory per instance.
    const auto q = dir.write("empty_elements.ply",
                             "ply\nformat binary_big_endian 1.0\nelement nothing 500000000\n"
                             "end_header\n");
    expect_refusal(import_error(q, quick()), q, "500000000 'nothing' elements");
}

TEST(DeclaredCounts, PlyGuardAcceptsRealFiles) {
    namespace fs = std::filesystem;
    std::size_t checked = 0;
    for (const auto& e : fs::recursive_directory_iterator("/usr/share/assimp/models/PLY")) {
        if (e.path().extension() != ".ply" || !e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        std::string head(detail::kGuardHeadBytes, '\0');
        in.read(head.data(), static_cast<std::streamsize>(head.size()));
        head.resize(static_cast<std::size_t>(in.gcount()));
        EXPECT_FALSE(detail::implausible_ply_header(head, fs::file_size(e.path()))) << e.path();
        ++checked;
    }
    EXPECT_GE(checked, 5u);
}

TEST(DeclaredCounts, PlyHeaderWithoutEndInTheGuardedPrefixIsRefused) {
    std::string head = "ply\nformat ascii 1.0\n";
    while (head.size() < detail::kGuardHeadBytes) head += "comment padding padding padding\n";
    head.resize(detail::kGuardHeadBytes);
    const auto why = detail::implausible_ply_header(head, head.size() + 100);
    ASSERT_TRUE(why);
    EXPECT_NE(why->find("no end_header"), std::string::npos);
}

TEST(DeclaredCounts, OffWithDimensionPrefixIsGuardedToo) {
    EXPECT_TRUE(detail::implausible_off_header("nOFF 3 900000000 1 0\n", 100));
    EXPECT_FALSE(
        detail::implausible_off_header("nOFF 3 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 41));
}

TEST(DeclaredCounts, OffDeclaringHalfABillionVerticesIsRefused) {
    ScratchDir dir;
    const auto p = dir.write("huge.off", "OFF\n500000000 1 0\n0 0 0\n3 0 0 0\n");
    expect_refusal(import_error(p, quick()), p, "OFF header declares 500000000 vertices");
}

TEST(DeclaredCounts, BinaryStlDeclaringMoreTrianglesThanItHoldsIsRefused) {
    ScratchDir dir;
    std::string stl(80, 'x');
    const std::uint32_t count = 1000000000;
    stl.append(reinterpret_cast<const char*>(&count), 4);
    stl.append(50, '\0');
    const auto p = dir.write("huge.stl", stl);
    expect_refusal(import_error(p, quick()), p, "binary STL header declares 1000000000 triangles");
}

TEST(DeclaredCounts, ObjWithTooManyLinesIsRefused) {
    ScratchDir dir;
    std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 2000; ++i) obj += "f 1 2 3\n";
    const auto p = dir.write("long.obj", obj);
    ImportOptions o = quick();
    o.limits.max_text_lines = 1000;
    expect_refusal(import_error(p, o), p, "OBJ has more than 1000 lines");
    o.limits.max_text_lines = 5000;
    EXPECT_EQ(import_model(p, o).triangle_count(), 2000u);
}

TEST(DeclaredCounts, PlyContentIsGuardedWhateverTheExtension) {
    ScratchDir dir;
    const auto p = dir.write("disguised.obj",
                             "ply\nformat ascii 1.0\nelement vertex 900000000\nproperty float x\n"
                             "end_header\n0\n");
    expect_refusal(import_error(p, quick()), p, "PLY header declares 900000000");
}

}  // namespace
}  // namespace bz::geo
