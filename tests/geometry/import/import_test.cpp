#include "geometry/import/import.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "geometry/line_mesh/line_mesh.h"
#include "gltf_test_files.h"
#include "import_test_util.h"
#include "support/scratch_dir.h"

namespace bz::geo {
namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models";

// A scratch folder per test.
class ImportTest : public ::testing::Test {
  protected:
    fs::path write(const std::string& name, const std::string& bytes) {
        return scratch_.write(name, bytes);
    }
    const fs::path& dir() const { return scratch_.path(); }

  private:
    bz::test::ScratchDir scratch_{"bz_geo_import"};
};

using test::import_error;  // runs import_model expecting a UserError; returns its message

void expect_one_line_naming(const std::string& message, const fs::path& path) {
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

bool contains(const TriMesh& m, glm::vec3 p) {
    return std::find(m.positions.begin(), m.positions.end(), p) != m.positions.end();
}

TEST(Import, RealModelsHaveTriangles) {
    for (const char* file : {"PLY/Wuson.ply", "OBJ/spider.obj", "Collada/duck.dae",
                             "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"}) {
        SCOPED_TRACE(file);
        const TriMesh m = import_model(kModels / file);
        EXPECT_GT(m.triangle_count(), 0u);
        for (const glm::vec3& p : m.positions) {
            ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        }
        MeshReport report;
        const AdjacencyMesh lines = build_line_mesh(m, &report);
        EXPECT_GT(lines.triangle_count(), 0u);
        EXPECT_LE(report.welded_vertices, m.positions.size());
    }
}

TEST_F(ImportTest, KeepsCoordinatesTriangulatesAndDropsPointsAndLines) {
    const fs::path p = write("mixed.obj",
                             "v 100 200 300\nv 101 200 300\nv 101 201 300\nv 100 201 300\n"
                             "v 5 5 5\nf 1 2 3 4\nl 1 5\np 5\n");
    const TriMesh m = import_model(p);
    EXPECT_EQ(m.triangle_count(), 2u);  // the quad
    EXPECT_TRUE(contains(m, {100, 200, 300}));
    EXPECT_TRUE(contains(m, {101, 201, 300}));
    for (std::uint32_t i : m.indices) EXPECT_NE(m.positions[i], glm::vec3(5, 5, 5));
}

TEST_F(ImportTest, AppliesNodeTransformsOncePerReferencingNode) {
    // One triangle mesh, referenced by two child nodes (translated) of a scaled root.
    write("tri.bin", test::triangle_buffer());
    const std::string buffer = R"({"uri": "tri.bin", "byteLength": 42})";
    const std::string nodes = R"([{"children": [1, 2], "scale": [2, 2, 2]},
                                  {"mesh": 0, "translation": [10, 0, 0]},
                                  {"mesh": 0, "translation": [0, 5, 0]}])";
    const fs::path gltf = write("instanced.gltf", test::gltf_json(buffer, nodes, "[0]"));
    const TriMesh m = import_model(gltf);
    ASSERT_EQ(m.triangle_count(), 2u);
    for (glm::vec3 p : {glm::vec3(20, 0, 0), glm::vec3(22, 0, 0), glm::vec3(20, 2, 0),
                        glm::vec3(0, 10, 0), glm::vec3(2, 10, 0), glm::vec3(0, 12, 0)}) {
        EXPECT_TRUE(contains(m, p)) << p.x << " " << p.y << " " << p.z;
    }
}

TEST_F(ImportTest, RejectsNaNAndInfWithTheFileName) {
    const fs::path nan_obj = write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    const fs::path inf_obj = write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 inf 0\nf 1 2 3\n");
    // Binary STL: 80-byte header, count, then normal + 3 corners + attribute per triangle.
    const float tri[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, std::nanf(""), 1, 0};
    std::string stl(80, '\0');
    const std::uint32_t count = 1;
    stl.append(reinterpret_cast<const char*>(&count), 4);
    stl.append(reinterpret_cast<const char*>(tri), sizeof tri);
    stl.append(2, '\0');
    const fs::path nan_stl = write("nan.stl", stl);
    const fs::path infinites = kModels / "glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb";
    for (const fs::path& p : {nan_obj, inf_obj, nan_stl, infinites}) {
        const std::string message = import_error(p);
        expect_one_line_naming(message, p);
        EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
    }
}

TEST_F(ImportTest, MissingFileAndFolderAreNamed) {
    const fs::path missing = dir() / "no_such_model.obj";
    std::string message = import_error(missing);
    expect_one_line_naming(message, missing);
    EXPECT_NE(message.find("not found"), std::string::npos);
    message = import_error(dir());
    expect_one_line_naming(message, dir());
    EXPECT_NE(message.find("not a regular file"), std::string::npos);
}

TEST_F(ImportTest, RejectsFilesOverTheSizeCapWithoutReadingThem) {
    const fs::path big = write("big.obj", "");
    fs::resize_file(big, kMaxModelFileBytes + 1);  // sparse: no disk used
    const std::string message = import_error(big);
    expect_one_line_naming(message, big);
    EXPECT_NE(message.find("over the limit"), std::string::npos);
}

TEST_F(ImportTest, FileWithoutTrianglesIsRejected) {
    const fs::path lines = write("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
    const std::string message = import_error(lines);
    expect_one_line_naming(message, lines);
    EXPECT_NE(message.find("no triangles"), std::string::npos);
}

TEST(Import, BrokenFilesThrowUserErrorNamingTheFile) {
    // Assimp's own collection of broken files (empty, malformed, absurd counts). One of them,
    // malformed2.obj, only names a missing material: its geometry is fine and it loads.
    std::size_t refused = 0, loaded = 0;
    for (const auto& entry : fs::directory_iterator(kModels / "invalid")) {
        SCOPED_TRACE(entry.path().string());
        try {
            loaded += import_model(entry.path()).triangle_count() > 0 ? 1 : 0;
        } catch (const UserError& e) {
            expect_one_line_naming(e.what(), entry.path());
            ++refused;
        }
    }
    EXPECT_GE(refused, 13u);
    EXPECT_LE(loaded, 1u);
    for (const char* file : {"empty.obj", "empty.ply", "malformed.obj", "empty.3ds"}) {
        expect_one_line_naming(import_error(kModels / "invalid" / file),
                               kModels / "invalid" / file);
    }
}

TEST(Import, OffHeaderWithAbsurdCountsIsRefusedBeforeAssimp) {
    // Assimp itself spends ~50 s and ~16 GB on this 309-byte file.
    const fs::path p = kModels / "invalid/OutOfMemory.off";
    const std::string message = import_error(p);
    expect_one_line_naming(message, p);
    EXPECT_NE(message.find("OFF header declares"), std::string::npos) << message;
}

}  // namespace
}  // namespace bz::geo
