#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

// The mesh's connected pieces (triangles joined by welded vertices), each with whether it is
// outward-closed on its own (watertight, every edge with one consistently wound neighbour,
// enclosing a positive volume) and its box. From outside an outward-closed piece's box, every
// back face of the piece lies behind the piece's own front faces, whatever the rest of the
// mesh is: a model made of closed solids and open sheets (a ship's hallway: panels around
// pipes and rivets) may skip the solids' back faces.
struct Pieces {
    struct Piece {
        bool outward_closed = true;
        std::size_t triangles = 0;
        Bounds box{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    };
    std::vector<std::uint32_t> piece_of_vertex;  // into `pieces`
    std::vector<Piece> pieces;
};
Pieces connected_pieces(const AdjacencyMesh& mesh);

// True when every edge has exactly one consistently wound neighbour (watertight) and the
// enclosed signed volume is positive (faces point outward). For such a mesh seen from outside
// its bounds, every back-facing triangle is hidden by the mesh itself, so the renderer may
// skip back faces in both the prepass and the line pass without changing the picture.
bool is_outward_closed(const AdjacencyMesh& mesh);
// The same from the mesh's pieces, where the caller has them already.
bool is_outward_closed(const Pieces& pieces);

}  // namespace bz::geo
