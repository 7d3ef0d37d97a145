#pragma once
// The Battlezone simulation: a fixed 60 Hz step driven by one TickCommand per tick, seeded,
// with no clock and no other input, so the same seed and commands give the same game.
#include <cstdint>
#include <optional>
#include <vector>

#include "game/world/events.h"
#include "game/world/field.h"
#include "game/world/obstacle_grid.h"
#include "game/world/tick_command.h"
#include "game/world/world_state.h"
#include "level/level.h"
#include "scene/factory_table.h"
#include "scene/frame_list.h"

namespace bz::game {

// Meshes for the objects the simulation creates itself (level objects come from factories).
struct ModelIds {
    scene::MeshId slow_tank = 0;
    scene::MeshId super_tank = 0;
    scene::MeshId missile = 0;
    scene::MeshId saucer = 0;
    scene::MeshId shell = 0;
    std::vector<scene::MeshId> debris;  // pieces; empty = use the shell mesh
};

enum class EnemyDirection : std::uint8_t { none, ahead, left, right, rear };

// What the tank's crew knows this tick: drives the messages, reticle and warnings.
struct Awareness {
    bool enemy_present = false;   // a hostile (not the saucer) is on the field
    bool enemy_in_range = false;  // within radar range
    bool in_sights = false;       // lined up with the gun and within shell range
    EnemyDirection direction = EnemyDirection::none;
    bool motion_blocked = false;
};

// What a level reload did to the game in play.
struct WorldReload {
    bool player_moved = false;   // it was inside an obstacle or off the new field (or wrapped
                                 // onto a smaller one)
    bool hostile_moved = false;  // likewise (placed anew, or gone when nowhere was free), or
                                 // wrapped onto a smaller field
};

struct RadarBlip {
    glm::dvec2 offset{0.0};  // relative to the player, rotated so +y is straight ahead, x right
    double distance = 0.0;
};

class World {
  public:
    // Throws UserError naming file:line:col when a level object's kind has no factory.
    World(const level::Level& level, std::uint64_t seed, const scene::FactoryTable& factories,
          ModelIds models, int lives = 3);

    void step(const TickCommand& command);

    // Swaps in an edited level while the game goes on: obstacles, field size and wrap, enemy
    // rules and style change; score, lives, timers and every moving thing stay. The tank and
    // the hostile move only when the new level has them inside an obstacle or off the field.
    // Deterministic (the same state and level give the same state). Throws UserError naming
    // file:line:col, with nothing changed, when the level does not build.
    WorldReload reload_level(const level::Level& level, const scene::FactoryTable& factories);
    // Throws UserError unless the level's field is one a world can have.
    static void check_field(const level::Level& level);

    // FNV-1a over every field of the current state (positions, timers, score, the RNG...).
    std::uint64_t state_hash() const;

    const WorldState& state() const { return cur_; }
    const WorldState& previous() const { return prev_; }
    const std::vector<scene::Entity>& obstacles() const { return obstacles_; }
    const Field& field() const { return field_; }
    const level::EnemyRules& rules() const { return rules_; }
    const std::vector<int>& bonus_scores() const { return bonus_scores_; }
    std::uint64_t seed() const { return seed_; }
    const std::vector<SoundEvent>& events() const { return events_; }
    float engine_level() const;

    Phase phase() const { return cur_.phase; }
    bool game_over() const { return cur_.phase == Phase::game_over; }
    int score() const { return cur_.score; }
    int lives() const { return cur_.lives; }

    Awareness awareness() const;
    double radar_range() const;
    // Whether a missile now flies the arcade's nastier way (rules().missile_nastier_after).
    bool missile_is_nasty() const;
    // The hostile as the radar shows it (never the saucer); empty when none or out of range.
    std::vector<RadarBlip> radar_blips() const;
    // Sweep angle in radians, clockwise from straight ahead, interpolated.
    double radar_sweep(double alpha) const;

    // The 3D part of a frame between the previous (alpha = 0) and current (alpha = 1) state:
    // first-person camera and one draw item per visible object. Obstacles beyond
    // draw_distance are left out.
    scene::FrameList interpolated_frame(double alpha, double fov_y_deg = 45.0,
                                        double draw_distance = 260.0) const;

    // Scenario hooks for tests and the attract demo: place a hostile or the saucer at an
    // offset from the player (x right, y ahead in the player's view), replacing any present.
    void spawn_hostile(HostileKind kind, glm::dvec2 view_offset,
                       double yaw_towards_player_deg = 0.0);
    void spawn_saucer(glm::dvec2 view_offset);

  private:
    void step_player(const PackedCommand& cmd);
    void step_hostile();
    void step_tank(Hostile& h);
    // The parts of step_tank: where the tank heads and how fast (its mode's course, which may
    // switch mode); a dodge when the player's gun is on it; a step forward, or a detour when
    // blocked; a shot when its gun is on the player.
    struct TankCourse {
        double yaw = 0.0;
        double throttle = 1.0;  // of full speed; negative backs off
    };
    TankCourse tank_course(Hostile& h, double dist, double face_player, double aggression);
    void tank_dodge(Hostile& h, glm::dvec2 to_player, double aggression);
    void tank_drive(Hostile& h, double speed);
    void tank_fire(Hostile& h, double dist, double face_player, double aggression);
    void step_missile(Hostile& h);
    void step_saucer();
    void step_shells();
    void step_debris();
    void step_spawning();
    void step_dying();
    void award_bonuses();

    bool try_spawn_hostile();
    // A legal place for a new hostile of `kind` around the player, or none after a few tries.
    std::optional<glm::dvec2> spawn_spot(HostileKind kind);
    void place_hostile(HostileKind kind, glm::dvec2 position, double yaw);
    // `yaw_offset` turns the shell off the gun's line (enemy aim error), radians.
    void fire_shell(const scene::Entity& from, bool from_player, double speed, double range,
                    double yaw_offset = 0.0);
    void destroy_hostile();
    void destroy_saucer();
    void kill_player();
    void add_score(int points);
    void spawn_debris(const glm::dvec3& at, const glm::vec3& color, int pieces, double power);

    // Collision against obstacles on the ground plane; `height` lets hopping things pass over.
    const scene::Entity* obstacle_at(glm::dvec2 p, double radius, double base_height = 0.0) const;
    // How far the eye backs off behind the tank's centre at `ground` facing `forward` (unit,
    // xz), so that an obstacle just ahead shows its edges instead of filling the view. The
    // view only: the simulation and its collision rule are untouched.
    double eye_backoff(glm::dvec2 ground, glm::dvec2 forward) const;
    bool blocked(glm::dvec2 p, double radius, bool for_player) const;
    glm::dvec2 player_ground() const { return ground(cur_.player.body.transform.position); }
    glm::dvec2 view_to_world(glm::dvec2 view_offset) const;

    // The level's obstacles placed on `field`; throws UserError (file:line:col).
    static std::vector<scene::Entity> build_obstacles(const level::Level& level,
                                                      const scene::FactoryTable& factories,
                                                      const Field& field);
    // After a reload (world_reload.cpp): move what the new level leaves in an illegal place.
    bool settle_player();
    bool settle_hostile();
    void settle_saucer_and_shells();
    // The nearest place within the field where a circle of `radius` touches no obstacle;
    // `from` itself when nothing is free.
    glm::dvec2 free_spot_near(glm::dvec2 from, double radius) const;

    Field field_;
    level::EnemyRules rules_;
    std::vector<int> bonus_scores_;  // the level's, increasing
    ModelIds models_;
    std::vector<scene::Entity> obstacles_;
    ObstacleGrid grid_;
    mutable std::vector<std::uint32_t> nearby_;  // scratch for obstacle_at
    glm::vec3 enemy_color_{0.2f, 1.0f, 0.3f};
    scene::Style style_ = scene::Style::vector;
    std::uint64_t seed_ = 0;
    WorldState prev_;
    WorldState cur_;
    std::vector<SoundEvent> events_;
};

// Degrees <-> radians and angle helpers shared by the world and the HUD.
double wrap_angle(double radians);  // into (-pi, pi]

}  // namespace bz::game
