#include "game/assets/models.h"

#include <glm/gtc/matrix_transform.hpp>
#include <stdexcept>

#include "scene/shapes.h"

namespace bz::game::models {

namespace {

using scene::shapes::append;
using scene::shapes::loft;
using scene::shapes::rect_ring;
using scene::shapes::Ring;

// Rectangle rings as (width, length, y, z offset of the centre).
Ring rect(float w, float l, float y, float z = 0.0f) {
    return rect_ring(w, l, y, {0.0f, z});
}

// Turns a model built along +y (nose up) to face -z.
glm::mat4 nose_forward(float lift) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), {0.0f, lift, 0.0f});
    return glm::rotate(m, glm::radians(-90.0f), {1.0f, 0.0f, 0.0f});
}

}  // namespace

geo::TriMesh slow_tank() {
    geo::TriMesh m;
    // Hull: sloped front and back plates over the treads, the front reaching further.
    append(m, loft({rect(2.8f, 3.4f, 0.0f), rect(3.0f, 4.6f, 0.5f, -0.1f),
                    rect(2.5f, 3.2f, 0.9f, 0.2f)}));
    // Turret, set back, with a sloped face.
    append(m, loft({rect(1.8f, 2.0f, 0.9f, 0.5f), rect(1.2f, 1.3f, 1.55f, 0.65f)}));
    // Barrel out of the turret face.
    append(m, scene::shapes::box({-0.12f, 1.12f, -2.7f}, {0.12f, 1.36f, 0.0f}));
    // Radar mast and dish at the back of the turret.
    append(m, scene::shapes::box({-0.05f, 1.55f, 0.9f}, {0.05f, 1.95f, 1.0f}));
    append(m, scene::shapes::box({-0.35f, 1.95f, 0.85f}, {0.35f, 2.1f, 1.05f}));
    return m;
}

geo::TriMesh super_tank() {
    geo::TriMesh m;
    // A long low wedge: the nose rises gently to a short deck.
    append(m, loft({rect(2.6f, 4.2f, 0.0f), rect(2.8f, 5.2f, 0.45f, -0.2f),
                    rect(2.2f, 2.8f, 0.75f, 0.6f)}));
    append(m, loft({rect(1.5f, 1.7f, 0.75f, 0.7f), rect(0.9f, 1.0f, 1.2f, 0.85f)}));
    append(m, scene::shapes::box({-0.1f, 0.9f, -3.4f}, {0.1f, 1.08f, 0.2f}));
    return m;
}

geo::TriMesh missile() {
    geo::TriMesh body;
    // Built nose-up along +y from the tail at y = 0, then turned to face -z.
    append(body, loft({scene::shapes::ellipse_ring(8, {0.28f, 0.28f}, 0.0f),
                       scene::shapes::ellipse_ring(8, {0.38f, 0.38f}, 0.6f),
                       scene::shapes::ellipse_ring(8, {0.38f, 0.38f}, 2.6f),
                       Ring{{{0.0f, 0.0f}}, 3.8f}}));
    // Four tail fins.
    for (int i = 0; i < 4; ++i) {
        glm::mat4 r =
            glm::rotate(glm::mat4(1.0f), glm::radians(45.0f + 90.0f * static_cast<float>(i)),
                        {0.0f, 1.0f, 0.0f});
        append(body,
               loft({Ring{{{0.3f, 0.06f}, {0.95f, 0.03f}, {0.95f, -0.03f}, {0.3f, -0.06f}}, 0.0f},
                     Ring{{{0.3f, 0.06f}, {0.35f, 0.03f}, {0.35f, -0.03f}, {0.3f, -0.06f}}, 1.0f}}),
               r);
    }
    geo::TriMesh m;
    // Centre the body about the middle so it pitches nicely; its base rides 0.5 up.
    append(m, body, nose_forward(0.5f) * glm::translate(glm::mat4(1.0f), {0.0f, -1.9f, 0.0f}));
    return m;
}

geo::TriMesh saucer() {
    using scene::shapes::ellipse_ring;
    return loft({ellipse_ring(12, {0.6f, 0.6f}, 0.0f), ellipse_ring(12, {1.9f, 1.9f}, 0.3f),
                 ellipse_ring(12, {0.9f, 0.9f}, 0.5f), ellipse_ring(12, {0.35f, 0.35f}, 0.85f)});
}

geo::TriMesh shell() {
    return loft(
        {Ring{{{0.0f, 0.0f}}, -0.22f}, rect(0.35f, 0.5f, 0.0f), Ring{{{0.0f, 0.0f}}, 0.22f}});
}

geo::TriMesh spark() {
    return loft(
        {Ring{{{5.0f, 3.0f}, {0.0f, -5.5f}, {-5.0f, 3.0f}}, -3.0f}, Ring{{{0.0f, 0.0f}}, 5.0f}});
}

std::vector<geo::TriMesh> debris() {
    std::vector<geo::TriMesh> pieces;
    // A wedge of armour.
    pieces.push_back(loft({Ring{{{0.6f, 0.4f}, {0.0f, -0.6f}, {-0.6f, 0.4f}}, -0.2f},
                           Ring{{{0.6f, 0.4f}, {0.0f, -0.6f}, {-0.6f, 0.4f}}, 0.2f}}));
    // A chunk of hull.
    pieces.push_back(scene::shapes::box({-0.5f, -0.25f, -0.35f}, {0.5f, 0.25f, 0.35f}));
    // A shard.
    pieces.push_back(loft(
        {Ring{{{0.5f, 0.3f}, {0.0f, -0.5f}, {-0.4f, 0.35f}}, -0.3f}, Ring{{{0.1f, 0.0f}}, 0.5f}}));
    // A length of barrel.
    pieces.push_back(scene::shapes::box({-0.12f, -0.12f, -0.9f}, {0.12f, 0.12f, 0.9f}));
    return pieces;
}

geo::TriMesh obstacle(const level::BuiltinKind& kind) {
    const auto w = static_cast<float>(kind.half_x * 2.0);
    const auto l = static_cast<float>(kind.half_z * 2.0);
    const auto h = static_cast<float>(kind.height);
    switch (kind.shape) {
        case level::KindShape::box:
            return loft({rect(w, l, 0.0f), rect(w, l, h)});
        case level::KindShape::pyramid:
            return loft({rect(w, l, 0.0f), Ring{{{0.0f, 0.0f}}, h}});
        case level::KindShape::model:
            break;
    }
    throw std::invalid_argument("obstacle(): kind '" + std::string(kind.name) +
                                "' has no built-in shape");
}

}  // namespace bz::game::models
