// Zip-based model files (.3mf and the like) whose entries inflate past the cap are refused
// from the central directory, before Assimp inflates anything; real ones still load.
#include <gtest/gtest.h>
#include <minizip/zip.h>

#include <chrono>
#include <string>
#include <vector>

#include "geometry/import/import_zip.h"
#include "import_test_util.h"

namespace bz::geo {
namespace {

using namespace test;  // ScratchDir, import_error, expect_refusal, quick, seconds_since

// A real bomb: `zeros` bytes of zeros, deflated (about 1000:1).
void add_zeros(zipFile zf, const char* name, std::size_t zeros) {
    zip_fileinfo info{};
    ASSERT_EQ(
        zipOpenNewFileInZip64(zf, name, &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED, 9, 1),
        ZIP_OK);
    const std::vector<char> block(1 << 20, '\0');
    for (std::size_t left = zeros; left > 0;) {
        const std::size_t n = std::min(left, block.size());
        ASSERT_EQ(zipWriteInFileInZip(zf, block.data(), static_cast<unsigned>(n)), ZIP_OK);
        left -= n;
    }
    ASSERT_EQ(zipCloseFileInZip(zf), ZIP_OK);
}

// A lying entry: three stored bytes declared as `declared` uncompressed bytes.
void add_lie(zipFile zf, const char* name, std::uint64_t declared) {
    zip_fileinfo info{};
    ASSERT_EQ(zipOpenNewFileInZip2_64(zf, name, &info, nullptr, 0, nullptr, 0, nullptr, 0, 0, 1, 1),
              ZIP_OK);
    ASSERT_EQ(zipWriteInFileInZip(zf, "abc", 3), ZIP_OK);
    ASSERT_EQ(zipCloseFileInZipRaw64(zf, declared, 0x352441c2u), ZIP_OK);
}

TEST(ZipBomb, ThreeMfInflatingPastTheCapIsRefusedBeforeInflating) {
    ScratchDir dir;
    const auto p = dir.path() / "bomb.3mf";
    zipFile zf = zipOpen64(p.c_str(), APPEND_STATUS_CREATE);
    ASSERT_NE(zf, nullptr);
    add_zeros(zf, "[Content_Types].xml", 100);
    add_zeros(zf, "3D/3dmodel.model", std::size_t{48} << 20);
    ASSERT_EQ(zipClose(zf, nullptr), ZIP_OK);
    ASSERT_LT(std::filesystem::file_size(p), std::uintmax_t{1} << 20);

    ImportOptions o = quick();
    o.limits.max_unzipped_bytes = std::uint64_t{16} << 20;
    const auto start = Clock::now();
    expect_refusal(import_error(p, o), p,
                   "zip entry '3D/3dmodel.model' inflates to 50331648 bytes");
    EXPECT_LT(seconds_since(start), 3.0);
}

TEST(ZipBomb, DeclaredGigabytesAreRefusedWithTheDefaultCap) {
    ScratchDir dir;
    const auto p = dir.path() / "liar.3mf";
    zipFile zf = zipOpen64(p.c_str(), APPEND_STATUS_CREATE);
    ASSERT_NE(zf, nullptr);
    add_lie(zf, "3D/3dmodel.model", std::uint64_t{3} << 30);
    ASSERT_EQ(zipClose(zf, nullptr), ZIP_OK);
    expect_refusal(import_error(p, quick()), p, "inflates to 3221225472 bytes");
}

TEST(ZipBomb, ManySmallEntriesAddUp) {
    ScratchDir dir;
    const auto p = dir.path() / "many.zae";
    zipFile zf = zipOpen64(p.c_str(), APPEND_STATUS_CREATE);
    ASSERT_NE(zf, nullptr);
    for (int i = 0; i < 20; ++i) {
        add_lie(zf, ("part" + std::to_string(i)).c_str(), std::uint64_t{20} << 20);
    }
    ASSERT_EQ(zipClose(zf, nullptr), ZIP_OK);
    // 20 x 20 MB: each entry is under the 256 MB cap, the sum is not.
    expect_refusal(import_error(p, quick()), p, "over the limit of 268435456 uncompressed bytes");
}

TEST(ZipBomb, TruncatedZipIsRefusedWithAMessage) {
    ScratchDir dir;
    const auto p = dir.write("cut.3mf", std::string("PK\x03\x04", 4) + std::string(200, 'x'));
    expect_refusal(import_error(p, quick()), p, "central directory cannot be read");
}

TEST(ZipBomb, RealThreeMfStillLoads) {
    const auto p = std::filesystem::path("/usr/share/assimp/models/3MF/box.3mf");
    EXPECT_GT(import_model(p, quick()).triangle_count(), 0u);
}

}  // namespace
}  // namespace bz::geo
