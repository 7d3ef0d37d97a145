// Every file a model refers to (an OBJ's mtllib, a glTF buffer uri) must lie in the folders
// the model may read from, after `..` and symbolic links: escapes are refused with a message
// naming the model, the reference and the reason. References inside still load.
#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "import_test_util.h"

namespace bz::geo {
namespace {

using namespace test;  // ScratchDir, import_error, expect_refusal, quick, seconds_since

const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

// level/ holds the model; outside/ is a sibling it must not read.
struct Layout {
    ScratchDir dir;
    std::filesystem::path level = dir.path() / "level";
    ImportOptions options() const {
        ImportOptions o = quick();
        o.allowed_folders = {level};
        return o;
    }
    Layout() {
        dir.write("outside/secret.bin", test::triangle_buffer());
        dir.write("outside/secret.mtl", "newmtl leaked\nKd 1 0 0\n");
        std::filesystem::create_directories(level);
    }
};

TEST(Confinement, MtllibEscapingWithDotDotIsRefused) {
    Layout l;
    const auto p = l.dir.write("level/m.obj", "mtllib ../outside/secret.mtl\n" + kTriangleObj);
    const std::string m = import_error(p, l.options());
    expect_refusal(m, p, "reference '");
    EXPECT_NE(m.find("outside/secret.mtl': leads outside the folders a model may read from"),
              std::string::npos)
        << m;
}

// A long reference is quoted with its middle cut out, so the message keeps both ends: where
// it starts and the file it names.
TEST(Confinement, LongReferenceIsQuotedWithBothEnds) {
    Layout l;
    const std::string deep = "../outside/" + std::string(200, 'd') + "/secret.mtl";
    const auto p = l.dir.write("level/m.obj", "mtllib " + deep + "\n" + kTriangleObj);
    const std::string m = import_error(p, l.options());
    const auto open = m.find("reference '");
    const auto close = m.find("': leads outside");
    ASSERT_NE(open, std::string::npos) << m;
    ASSERT_NE(close, std::string::npos) << m;
    const std::string quoted = m.substr(open + 11, close - open - 11);
    EXPECT_LE(quoted.size(), 120u) << quoted;
    EXPECT_NE(quoted.find("..."), std::string::npos) << quoted;
    EXPECT_EQ(quoted.substr(quoted.size() - 11), "/secret.mtl") << quoted;
    EXPECT_EQ(quoted.front(), '/') << quoted;
}

TEST(Confinement, MtllibNamingEtcPasswdRelativelyIsRefused) {
    Layout l;
    const auto p =
        l.dir.write("level/m.obj", "mtllib ../../../../../../../../etc/passwd\n" + kTriangleObj);
    expect_refusal(import_error(p, l.options()), p, "etc/passwd': leads outside");
}

TEST(Confinement, GltfBufferUriEscapingIsRefused) {
    Layout l;
    const auto p = l.dir.write(
        "level/m.gltf", test::gltf_json(R"({"uri": "../outside/secret.bin", "byteLength": 42})",
                                        R"([{"mesh": 0}])", "[0]"));
    expect_refusal(import_error(p, l.options()), p, "secret.bin': leads outside");
}

TEST(Confinement, GltfBufferUriNamingEtcPasswdIsRefused) {
    Layout l;
    for (const char* uri : {"../../../../../../../../../etc/passwd", "/etc/passwd"}) {
        const auto p = l.dir.write(
            "level/m.gltf",
            test::gltf_json(std::string(R"({"uri": ")") + uri + R"(", "byteLength": 42})",
                            R"([{"mesh": 0}])", "[0]"));
        const std::string m = import_error(p, l.options());
        SCOPED_TRACE(uri);
        EXPECT_EQ(m.rfind(p.string() + ": error: ", 0), 0u) << m;
        // Refused by confinement, never read: nothing of the file ends up in the message.
        EXPECT_EQ(m.find("root:"), std::string::npos) << m;
        EXPECT_NE(m.find("etc/passwd"), std::string::npos) << m;
    }
}

TEST(Confinement, SymlinkLeadingOutsideIsRefused) {
    Layout l;
    std::filesystem::create_symlink(l.dir.path() / "outside" / "secret.bin", l.level / "tri.bin");
    const auto p = l.dir.write(
        "level/m.gltf",
        test::gltf_json(R"({"uri": "tri.bin", "byteLength": 42})", R"([{"mesh": 0}])", "[0]"));
    expect_refusal(import_error(p, l.options()), p, "tri.bin': leads outside");
}

TEST(Confinement, ModelItselfOutsideTheFoldersIsRefused) {
    Layout l;
    const auto p = l.dir.write("outside/m.obj", kTriangleObj);
    expect_refusal(import_error(p, l.options()), p, "outside the folders");
}

TEST(Confinement, ReferencesInsideAnyAllowedFolderLoad) {
    Layout l;
    // The level folder and a data folder: a model in one may use a file in the other.
    l.dir.write("data/shared.mtl", "newmtl green\nKd 0 1 0\n");
    l.dir.write("level/tri.bin", test::triangle_buffer());
    const auto obj =
        l.dir.write("level/m.obj", "mtllib ../data/shared.mtl\nusemtl green\n" + kTriangleObj);
    const auto gltf = l.dir.write(
        "level/m.gltf",
        test::gltf_json(R"({"uri": "tri.bin", "byteLength": 42})", R"([{"mesh": 0}])", "[0]"));
    ImportOptions o = l.options();
    o.allowed_folders.push_back(l.dir.path() / "data");
    EXPECT_EQ(import_model(obj, o).triangle_count(), 1u);
    EXPECT_EQ(import_model(gltf, o).triangle_count(), 1u);
    // Without the data folder, the same OBJ is refused.
    expect_refusal(import_error(obj, l.options()), obj, "shared.mtl': leads outside");
}

TEST(Confinement, DefaultIsTheModelsOwnFolder) {
    Layout l;
    const auto p = l.dir.write("level/m.obj", "mtllib ../outside/secret.mtl\n" + kTriangleObj);
    expect_refusal(import_error(p, quick()), p, "leads outside");
}

TEST(Confinement, BareNamesAreTakenRelativeToTheModelAndProbesDoNotFail) {
    // LWS names its objects bare and probes "../NAME" first; Ogre names its .material file
    // bare. Bare names resolve in the model's folder (not the working folder), and a probe
    // outside the folders only answers "no".
    const std::filesystem::path models = "/usr/share/assimp/models";
    EXPECT_GT(import_model(models / "LWS/move_x.lws", quick()).triangle_count(), 0u);
    EXPECT_GT(import_model(models / "Ogre/TheThing/Mesh.mesh.xml", quick()).triangle_count(), 0u);
}

}  // namespace
}  // namespace bz::geo
