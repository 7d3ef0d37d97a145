#pragma once
// A level as plain data: what the TOML file says, after validation, with defaults filled in.
// The level loader produces it; the game turns it into entities through the factory table.
// Every value keeps where it came from so later checks can still report file:line:col.
#include <cstdint>
#include <filesystem>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

namespace bz::level {

struct SourcePos {
    std::string file;
    int line = 0;
    int column = 0;
};

struct ObjectDesc {
    std::string kind;             // "cube", "pyramid", "tall_box", ... or "model"
    std::filesystem::path model;  // resolved path, only for kind == "model"
    glm::dvec3 position{0.0};     // world units; y up; the ground is y = 0
    double heading_deg = 0.0;     // rotation about +y: 0 faces -z, +90 faces -x (left)
    double scale = 1.0;
    glm::vec3 color{0.2f, 1.0f, 0.3f};  // linear RGB line colour
    SourcePos pos;
    // Radius of a circle around `position` (xz plane) that holds the whole footprint, already
    // multiplied by `scale`: from kinds.h for built-in kinds, from the `radius` key for models.
    double footprint_radius = 0.0;
};

// How hard the game plays. The level names its default; the player's setting or --difficulty
// wins. game/difficulty/difficulty.h turns a level's rules into the rules of one difficulty.
enum class Difficulty : std::uint8_t { easy, normal, arcade };

// The enemy rules and the scoring, after the 1980 operator defaults where those are known
// (missiles from 10,000; tanks 1,000, missiles 2,000, super tanks 3,000, the saucer 5,000).
// These are the values of the "normal" difficulty.
struct EnemyRules {
    bool slow_tank = true;
    bool super_tank = true;
    bool missile = true;
    bool saucer = true;
    int super_tank_score = 10000;  // super tanks may appear from this score
    int missile_score = 10000;     // missiles may appear from this score
    int saucer_score = 2000;       // the saucer may appear from this score
    // The arcade's rule: missiles turn nastier this many points after missile_score (see
    // game/world/tuning.h). A game rule, not a level key: no level file sets it and the level
    // hashes leave it out; replays record it, and one recorded before it existed plays with 0
    // (never), as it was played.
    int missile_nastier_after = 25000;
    double spawn_min_distance = 40.0;
    double spawn_max_distance = 90.0;
    double spawn_rear_chance = 0.1;  // share of spawns placed in the 90 degrees behind the player
    double aggression = 0.5;         // 0 = passive, 1 = relentless
    double fire_interval = 6.0;      // seconds an enemy tank reloads between shots
    double aim_error_deg = 6.0;      // an enemy shell leaves up to this far off the gun's line
    bool hold_fire = false;          // tanks shoot only once the player has fired at them
    int slow_tank_points = 1000;
    int super_tank_points = 3000;
    int missile_points = 2000;
    int saucer_points = 5000;
    Difficulty difficulty = Difficulty::normal;  // the level's default difficulty
};

struct Backdrop {
    // (azimuth degrees 0..360, height in degrees above horizon). Azimuths here are compass
    // bearings: 0 towards -z, 90 towards +x, clockwise seen from above.
    std::vector<glm::dvec2> mountains;
    bool volcano = true;
    double volcano_azimuth_deg = 60.0;
    bool moon = true;
    double moon_azimuth_deg = 300.0;
    double moon_elevation_deg = 18.0;
};

struct CameraKey {
    double time = 0.0;  // seconds
    glm::dvec3 eye{0.0};
    glm::dvec3 target{0.0};
};

struct RenderSettings {
    std::string style = "vector";     // a scene::Style name (scene/style.h); old names too
    std::string preset = "balanced";  // "fast", "balanced", "high"
    std::optional<double> line_width_px;
    std::optional<double> crease_angle_deg;
    std::optional<double> bloom_strength;
    // The vector beam's look ("classic" or "mame"), Battlezone's colour overlay and the
    // original's ~41 Hz refresh with frames held; unset: the player's settings decide.
    std::optional<std::string> beam;
    std::optional<bool> overlay;
    std::optional<bool> hold_41hz;
    std::optional<std::string> line_method;  // "compute" or "geometry_shader"; none: the preset's
    // Edges between faces of different materials (imported models' parts) drawn as lines;
    // unset: off (render::RenderSettings::material_lines).
    std::optional<bool> material_lines;
    // Where objects' surfaces cross (an obstacle sunk into another, a model's parts pushed
    // into each other) drawn as lines; unset: off (render::RenderSettings::intersection_lines).
    std::optional<bool> intersection_lines;
    // Whether the file set style / preset (else the defaults above): `play` lets a level's
    // own choice win over the player's settings file, but not a default.
    bool style_given = false;
    bool preset_given = false;
};

inline constexpr int kDefaultMenuOrder = 100;
inline constexpr int kMaxMenuOrder = 1000;

struct Level {
    int version = 1;
    std::string name;
    std::string author;
    std::string description;  // one or two sentences for a level menu; may be empty
    // The level menu: false keeps a scene that is not a game (a benchmark) out of the list
    // (it still loads by path); lower menu_order comes first, then the name.
    bool listed = true;
    int menu_order = kDefaultMenuOrder;
    std::filesystem::path file;  // the file it was loaded from
    // The canonical folders its models, and every file a model refers to, may be read from:
    // the level's own folder and the project's data/ folder (empty for a built-in level).
    std::vector<std::filesystem::path> model_folders;
    double field_size = 400.0;  // square field, centred on the origin, side in world units
    bool wrap = true;           // leaving one edge enters the opposite one
    glm::dvec3 player_start{0.0};
    double player_heading_deg = 0.0;
    int player_lives = 3;                          // tanks at the start of a game
    std::vector<int> bonus_scores{15000, 100000};  // a bonus tank at each, increasing
    std::vector<ObjectDesc> obstacles;
    EnemyRules enemies;
    Backdrop backdrop;
    RenderSettings render;
    std::vector<CameraKey> camera_path;  // sorted by time; may be empty
};

}  // namespace bz::level
