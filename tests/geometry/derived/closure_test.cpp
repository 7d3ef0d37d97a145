// is_outward_closed decides whether the renderer may cull back faces: only for watertight
// meshes every piece of which encloses a positive volume.
#include "geometry/derived/closure.h"

#include <gtest/gtest.h>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace {

using namespace bz::geo;

// Appends `b` to `a`, each vertex moved by `offset`, optionally wound inside out.
TriMesh joined(TriMesh a, const TriMesh& b, glm::vec3 offset, bool flip_b) {
    const auto base = static_cast<std::uint32_t>(a.positions.size());
    for (const glm::vec3& p : b.positions) a.positions.push_back(p + offset);
    for (std::size_t i = 0; i + 2 < b.indices.size(); i += 3) {
        a.indices.push_back(base + b.indices[i]);
        a.indices.push_back(base + b.indices[flip_b ? i + 2 : i + 1]);
        a.indices.push_back(base + b.indices[flip_b ? i + 1 : i + 2]);
    }
    return a;
}

TEST(Closure, ClosedBoxIsOutwardClosed) {
    EXPECT_TRUE(is_outward_closed(build_line_mesh(box(glm::vec3(1.0f)))));
}

TEST(Closure, OpenBoxIsNot) {
    EXPECT_FALSE(is_outward_closed(build_line_mesh(open_box(glm::vec3(1.0f)))));
}

TEST(Closure, TwoOutwardBoxesAre) {
    const TriMesh m = joined(box(glm::vec3(1.0f)), box(glm::vec3(0.5f)), {5.0f, 0.0f, 0.0f}, false);
    EXPECT_TRUE(is_outward_closed(build_line_mesh(m)));
}

// A big outward box and a small inside-out one: the total volume is positive, but culling
// the small box's "back" faces would remove its visible outside (a roof over rafters).
TEST(Closure, AnInsideOutPieceMakesTheMeshNotOutwardClosed) {
    const TriMesh m = joined(box(glm::vec3(2.0f)), box(glm::vec3(0.5f)), {6.0f, 0.0f, 0.0f}, true);
    EXPECT_FALSE(is_outward_closed(build_line_mesh(m)));
}

// Per piece: a closed box, an open box, an inside-out box and a sheet, in one mesh.
TEST(Closure, EachPieceIsJudgedOnItsOwnWithItsBox) {
    TriMesh m = joined(box(glm::vec3(1.0f)), open_box(glm::vec3(1.0f)), {4.0f, 0.0f, 0.0f}, false);
    m = joined(m, box(glm::vec3(0.5f)), {8.0f, 0.0f, 0.0f}, true);
    m = joined(m, grid(2, 2, 1.0f, 2), {0.0f, 5.0f, 0.0f}, false);
    const AdjacencyMesh mesh = build_line_mesh(m);
    const Pieces p = connected_pieces(mesh);
    ASSERT_EQ(p.pieces.size(), 4u);
    const auto piece_at = [&](glm::vec3 at) {
        for (std::uint32_t v = 0; v < mesh.positions.size(); ++v)
            if (glm::distance(mesh.positions[v], at) < 1e-4f) return p.pieces[p.piece_of_vertex[v]];
        ADD_FAILURE() << "no vertex at " << at.x << "," << at.y << "," << at.z;
        return Pieces::Piece{};
    };
    const Pieces::Piece closed = piece_at({1.0f, 1.0f, 1.0f});
    EXPECT_TRUE(closed.outward_closed);
    EXPECT_EQ(closed.triangles, 12u);
    EXPECT_EQ(closed.box.min, glm::vec3(-1.0f));
    EXPECT_EQ(closed.box.max, glm::vec3(1.0f));
    EXPECT_FALSE(piece_at({5.0f, 1.0f, 1.0f}).outward_closed) << "open box";
    EXPECT_FALSE(piece_at({8.5f, 0.5f, 0.5f}).outward_closed) << "inside out";
    EXPECT_FALSE(piece_at({-1.0f, 5.0f, -1.0f}).outward_closed) << "sheet";
    EXPECT_FALSE(is_outward_closed(mesh));
    EXPECT_FALSE(is_outward_closed(p));
}

// From the pieces the answer is the mesh's own (MeshCache::upload finds them once for this
// and for the triangle clusters); an empty mesh is not closed either way.
TEST(Closure, ThePiecesGiveTheMeshsAnswer) {
    const TriMesh two =
        joined(box(glm::vec3(1.0f)), box(glm::vec3(0.5f)), {5.0f, 0.0f, 0.0f}, false);
    const TriMesh flipped =
        joined(box(glm::vec3(2.0f)), box(glm::vec3(0.5f)), {6.0f, 0.0f, 0.0f}, true);
    for (const TriMesh& m : {box(glm::vec3(1.0f)), open_box(glm::vec3(1.0f)), two, flipped}) {
        const AdjacencyMesh mesh = build_line_mesh(m);
        EXPECT_EQ(is_outward_closed(connected_pieces(mesh)), is_outward_closed(mesh));
    }
    EXPECT_FALSE(is_outward_closed(Pieces{}));
    EXPECT_FALSE(is_outward_closed(AdjacencyMesh{}));
}

}  // namespace
