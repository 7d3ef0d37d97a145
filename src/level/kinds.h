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
    // > 0: what blocks tanks, shells and missiles is a circle of this radius about the origin
    // (the 1980 arcade's rule: each obstacle is a point with a collision radius); 0: the base.
    double collision_radius = 0.0;
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
    // The 1980 arcade's four shapes. The ROM table (stephenlclarke/battlezone,
    // assets/arcade/battlefield.txt, after MAME's `bzone`) gives each obstacle a collision
    // radius: wide pyramid 4, narrow pyramid 3.25, tall box 3.25, short box 3.75, in the
    // units of its 256-unit field. The shapes are that remake's drawn proportions (its
    // obstacle vertex tables times their per-kind scales), in the same units: base width :
    // height 7.92 : 4.56 (wide pyramid), 4.32 x 5.04 : 6.0 (narrow pyramid), 3.6 : 9.2 (tall
    // box), 4.8 : 5.6 (short box). The base may reach past the collision circle, as there.
    {"arcade_wide_pyramid", KindShape::pyramid, 3.96, 3.96, 4.56, 5.6002857069974565,
     "1980 arcade wide pyramid, 7.92 wide, 4.56 high, blocks within 4", 4.0},
    {"arcade_narrow_pyramid", KindShape::pyramid, 2.16, 2.52, 6.0, 3.3190360046254397,
     "1980 arcade narrow pyramid, 4.32 x 5.04 base, 6 high, blocks within 3.25", 3.25},
    {"arcade_tall_box", KindShape::box, 1.8, 1.8, 9.2, 2.545584412271571,
     "1980 arcade tall box, 3.6 wide, 9.2 high, blocks within 3.25", 3.25},
    {"arcade_short_box", KindShape::box, 2.4, 2.4, 5.6, 3.394112549695428,
     "1980 arcade short box, 4.8 wide, 5.6 high, blocks within 3.75", 3.75},
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
