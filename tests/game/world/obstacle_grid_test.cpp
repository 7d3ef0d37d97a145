#include "game/world/obstacle_grid.h"

#include <gtest/gtest.h>

#include "core/rng.h"
#include "game/world/collision.h"

namespace bz::game {
namespace {

// The grid must never miss an obstacle a full scan would find.
void check_against_scan(const Field& field, std::uint64_t seed) {
    Rng rng(seed);
    std::vector<scene::Entity> obstacles;
    const double half = field.size() * 0.5;
    for (int i = 0; i < 300; ++i) {
        scene::Entity e;
        e.transform.position = {rng.uniform(-half, half), 0.0, rng.uniform(-half, half)};
        e.transform.yaw = rng.uniform(-3.0, 3.0);
        e.transform.scale = rng.uniform(0.5, 3.0);
        e.collider = {
            scene::ColliderShape::box, 0.0, {rng.uniform(0.5, 10.0), rng.uniform(0.5, 3.0)}, 5.0};
        obstacles.push_back(e);
    }
    const ObstacleGrid grid(obstacles, field);
    std::vector<std::uint32_t> near;
    for (int q = 0; q < 3000; ++q) {
        // Some queries off the field, to exercise wrapping and clamping.
        const glm::dvec2 p{rng.uniform(-half * 1.1, half * 1.1),
                           rng.uniform(-half * 1.1, half * 1.1)};
        const double r = rng.uniform(0.1, 10.0);
        grid.near(p, r, near);
        ASSERT_TRUE(std::is_sorted(near.begin(), near.end()));
        for (std::uint32_t k = 0; k < obstacles.size(); ++k) {
            const scene::Entity& o = obstacles[k];
            const glm::dvec2 off = field.delta(ground(o.transform.position), p);
            if (circle_hits(o.collider, o.transform.yaw, o.transform.scale, off, r)) {
                ASSERT_TRUE(std::binary_search(near.begin(), near.end(), k))
                    << "query " << q << " missed obstacle " << k;
            }
        }
    }
}

TEST(ObstacleGrid, NeverMissesWhatAScanFinds_Wrapping) {
    check_against_scan(Field(400.0, true), 1);
}
TEST(ObstacleGrid, NeverMissesWhatAScanFinds_Closed) {
    check_against_scan(Field(300.0, false), 2);
}
TEST(ObstacleGrid, TinyField) {
    check_against_scan(Field(20.0, true), 3);
}

TEST(ObstacleGrid, EmptyAndFar) {
    const ObstacleGrid empty({}, Field(400.0, true));
    std::vector<std::uint32_t> near{7};
    empty.near({0, 0}, 5.0, near);
    EXPECT_TRUE(near.empty());
}

}  // namespace
}  // namespace bz::game
