#pragma once
// Generated meshes for tests, benchmarks and the game. Each is built the way an exporter would
// write it (vertices split at hard edges and texture seams), so welding has work to do.
// Counter-clockwise seen from outside is the front. Sizes must be positive and counts at
// least the stated minimum, else std::invalid_argument.
#include <cstdint>
#include <glm/glm.hpp>

#include "geometry/mesh.h"

namespace bz::geo {

// Axis-aligned box centred on the origin: 24 vertices (4 per face), 12 triangles.
TriMesh box(glm::vec3 half_extents);

// box() without its +y face: 20 vertices, 10 triangles, a 4-edge rim at the top.
TriMesh open_box(glm::vec3 half_extents);

// Sphere centred on the origin, poles on the y axis. rings >= 2 bands from pole to pole,
// segments >= 3 around. Grid of (rings + 1) x (segments + 1) vertices: the seam column and the
// pole rows are duplicated. 2 * segments * (rings - 1) triangles.
TriMesh uv_sphere(float radius, std::uint32_t rings, std::uint32_t segments);

// Flat plane in y = 0 facing +y, centred on the origin: nx * nz square cells of side `size`,
// 2 triangles each. Cells are grouped into tiles of tile x tile cells with their own vertices,
// so every tile border is a seam of duplicated vertices.
TriMesh grid(std::uint32_t nx, std::uint32_t nz, float size, std::uint32_t tile);

// Square base of half width half_base in y = 0, apex at (0, height, 0); 6 triangles, vertices
// split per face.
TriMesh pyramid(float half_base, float height);

// Capped cylinder along y, centred on the origin, segments >= 3. Side and caps have their own
// vertices and the side has a duplicated seam column. 4 * segments triangles.
TriMesh cylinder(float radius, float half_height, std::uint32_t segments);

// Three unit quads (two triangles each) sharing the edge (0,0,0)-(0,1,0): a non-manifold edge.
TriMesh fin();

// The mesh plus a copy of every face wound the other way, on copied vertices (as files with
// an inward-facing copy of every face are written).
TriMesh twin_faced(const TriMesh& mesh);

}  // namespace bz::geo
