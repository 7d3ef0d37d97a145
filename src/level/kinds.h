#pragma once
// The built-in obstacle kinds a level may name, with their sizes: the one table both the level
// loader (footprints for the placement checks) and the game (meshes, colliders) build from.
//
// Conventions, shared with the game: world units, y up, the ground is y = 0. A built-in object
// stands on its local origin: the box or pyramid base spans [-half_x, half_x] x [-half_z, half_z]
// at y = 0 and it rises to y = height. An object is placed by scaling uniformly, then rotating
// by heading_deg about +y (glm::rotate(radians(heading), {0, 1, 0})), then translating.
#include <span>
#include <string_view>

namespace bz::level {

enum class KindShape {
    box,      // rectangular block, flat top
    pyramid,  // rectangular base, apex at (0, height, 0)
    model,    // a mesh file named by the obstacle's `model` key
};

struct BuiltinKind {
    std::string_view name;
    KindShape shape;
    double half_x;            // world units at scale 1
    double half_z;            // world units at scale 1
    double height;            // world units at scale 1
    double footprint_radius;  // circle about the origin that holds the base, at scale 1
    std::string_view summary;
};

// For "model" the sizes are unknown until the mesh is imported, which level loading does not
// do; the radius below is the default footprint a level may override with `radius`.
inline constexpr BuiltinKind kBuiltinKinds[] = {
    {"cube", KindShape::box, 2.5, 2.5, 5.0, 3.5355339059327378, "5 x 5 x 5 block"},
    {"pyramid", KindShape::pyramid, 3.0, 3.0, 6.0, 4.2426406871192848,
     "square pyramid, 6 wide, 6 high"},
    {"tall_box", KindShape::box, 1.5, 1.5, 9.0, 2.1213203435596424, "3 x 3 pillar, 9 high"},
    {"short_box", KindShape::box, 4.0, 2.0, 2.5, 4.4721359549995796,
     "8 long, 4 deep, 2.5 high slab"},
    {"wall", KindShape::box, 10.0, 0.5, 4.0, 10.012492197250394,
     "20 long, 1 thick, 4 high wall segment (mazes)"},
    {"model", KindShape::model, 0.0, 0.0, 0.0, 3.0, "a mesh file given by `model`"},
};

// The footprint of the player's tank at the start, for the "overlaps the player start" check.
inline constexpr double kPlayerFootprintRadius = 3.0;

inline std::span<const BuiltinKind> builtin_kinds() {
    return kBuiltinKinds;
}

// nullptr when `name` is not a kind.
inline const BuiltinKind* find_kind(std::string_view name) {
    for (const auto& k : kBuiltinKinds) {
        if (k.name == name) return &k;
    }
    return nullptr;
}

}  // namespace bz::level
