// Primitives made of flat faces: box, open box, pyramid, fin, plus twin_faced.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/generated/primitives.h"

namespace bz::geo {
namespace {

std::uint32_t add_vertex(TriMesh& m, glm::vec3 p) {
    m.positions.push_back(p);
    return static_cast<std::uint32_t>(m.positions.size() - 1);
}

void add_triangle(TriMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    m.indices.insert(m.indices.end(), {a, b, c});
}

// A quad on its own four vertices; corners counter-clockwise seen from the front.
void add_quad(TriMesh& m, glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec3 p3) {
    const std::uint32_t a = add_vertex(m, p0), b = add_vertex(m, p1);
    const std::uint32_t c = add_vertex(m, p2), d = add_vertex(m, p3);
    add_triangle(m, a, b, c);
    add_triangle(m, a, c, d);
}

// The face of a box on axis `axis` (0..2) facing `sign`. With tangents u, v such that
// u x v is the outward normal, corners -u-v, +u-v, +u+v, -u+v run counter-clockwise.
void add_box_face(TriMesh& m, glm::vec3 half, int axis, float sign) {
    glm::vec3 n(0.0f), u(0.0f), v(0.0f);
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    n[axis] = sign * half[axis];
    u[sign > 0 ? a1 : a2] = half[sign > 0 ? a1 : a2];
    v[sign > 0 ? a2 : a1] = half[sign > 0 ? a2 : a1];
    add_quad(m, n - u - v, n + u - v, n + u + v, n - u + v);
}

void check_positive(glm::vec3 v, const char* what) {
    if (!(v.x > 0.0f && v.y > 0.0f && v.z > 0.0f)) {
        throw std::invalid_argument(std::string(what) + ": sizes must be positive");
    }
}

TriMesh box_faces(glm::vec3 half, bool with_top) {
    check_positive(half, "box");
    TriMesh m;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            if (!with_top && axis == 1 && sign > 0) continue;
            add_box_face(m, half, axis, sign);
        }
    }
    return m;
}

}  // namespace

TriMesh box(glm::vec3 half_extents) {
    return box_faces(half_extents, true);
}

TriMesh open_box(glm::vec3 half_extents) {
    return box_faces(half_extents, false);
}

TriMesh pyramid(float half_base, float height) {
    check_positive({half_base, height, 1.0f}, "pyramid");
    const float h = half_base;
    // Base corners counter-clockwise seen from above, so (b[k], b[k+1], apex) faces outward
    // and the base, walked backwards, faces down.
    const glm::vec3 b[4] = {{-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {h, 0, -h}};
    const glm::vec3 apex(0.0f, height, 0.0f);
    TriMesh m;
    add_quad(m, b[3], b[2], b[1], b[0]);
    for (int k = 0; k < 4; ++k) {
        const std::uint32_t p = add_vertex(m, b[k]), q = add_vertex(m, b[(k + 1) % 4]);
        add_triangle(m, p, q, add_vertex(m, apex));
    }
    return m;
}

TriMesh fin() {
    TriMesh m;
    const std::uint32_t s0 = add_vertex(m, {0, 0, 0}), s1 = add_vertex(m, {0, 1, 0});
    for (int k = 0; k < 3; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / 3.0;
        const glm::vec3 d(static_cast<float>(std::cos(angle)), 0.0f,
                          static_cast<float>(std::sin(angle)));
        const std::uint32_t p0 = add_vertex(m, d), p1 = add_vertex(m, d + glm::vec3(0, 1, 0));
        add_triangle(m, s0, p0, p1);
        add_triangle(m, s0, p1, s1);
    }
    return m;
}

TriMesh twin_faced(const TriMesh& mesh) {
    TriMesh m = mesh;
    const auto n = static_cast<std::uint32_t>(mesh.positions.size());
    m.positions.insert(m.positions.end(), mesh.positions.begin(), mesh.positions.end());
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        add_triangle(m, mesh.indices[i] + n, mesh.indices[i + 2] + n, mesh.indices[i + 1] + n);
    }
    return m;
}

}  // namespace bz::geo
