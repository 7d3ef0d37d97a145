#pragma once
// What every object in the world is made of: where it is, which shared mesh shows it, what it
// bumps into and how it behaves. Level objects, tanks, shells and debris all use this.
#include <cstdint>
#include <glm/glm.hpp>

#include "scene/frame_list.h"

namespace bz::scene {

// Position in world units (y up, the ground is y = 0) and orientation as yaw about +y, then
// pitch about the object's x axis, then roll about its z axis, all in radians. A model faces
// -z at yaw 0; positive yaw turns it to the left (counter-clockwise seen from above).
struct Transform {
    glm::dvec3 position{0.0};
    double yaw = 0.0;
    double pitch = 0.0;
    double roll = 0.0;
    double scale = 1.0;

    glm::dmat4 matrix() const;
    // The unit vector the object faces on the ground plane.
    glm::dvec3 forward() const;
};

// Shapes for collision on the ground plane, with a height so that shells and hopping missiles
// can pass over low things.
enum class ColliderShape : std::uint8_t { none, circle, box };

struct Collider {
    ColliderShape shape = ColliderShape::none;
    double radius = 0.0;          // circle
    glm::dvec2 half_extent{0.0};  // box, in the object's own x and z before yaw
    double height = 0.0;          // top of the collider above the object's base
};

enum class Behaviour : std::uint8_t {
    inert,     // drawn only
    obstacle,  // static; blocks tanks and shells
    player,
    slow_tank,
    super_tank,
    missile,
    saucer,
    shell,
    debris,
};

struct Entity {
    Transform transform;
    MeshId mesh = 0;
    Collider collider;
    Behaviour behaviour = Behaviour::inert;
    glm::vec3 color{0.2f, 1.0f, 0.3f};
};

}  // namespace bz::scene
