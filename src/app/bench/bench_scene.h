#pragma once
// The frames a benchmark renders, the same on every machine: the level simulated at a fixed
// 1/60 s step (one tick per frame), seen from the level's benchmark camera path, or a replay
// played back through the game's replay Player and seen through the player's own eyes.
// The scene comes from the game (World, Assets, backdrop, HUD): no second scene builder.
#include <memory>
#include <optional>
#include <string>

#include "game/assets/assets.h"
#include "game/records/replay.h"
#include "game/world/world.h"
#include "level/level.h"
#include "scene/frame_list.h"
#include "scene/mesh_library.h"
#include "scene/vector_font.h"

namespace bz::app {

inline constexpr double kBenchStep = 1.0 / 60.0;  // simulated seconds per frame

// The camera on a level's path at `seconds`: eye and target interpolated linearly between
// keys, the path repeated after its last key. Nothing when the level has no path.
std::optional<scene::Camera> camera_on_path(const level::Level& level, double seconds,
                                            double fov_y_deg);

class BenchScene {
  public:
    // Throws UserError when the level's objects or models do not load, or the replay was
    // recorded on another level.
    BenchScene(level::Level level, std::optional<game::replay::Replay> replay,
               double fov_y_deg = 45.0);
    ~BenchScene();

    // Steps one tick and returns the frame at the new time. False when the replay has ended.
    bool next(scene::FrameList& out, double aspect);
    double seconds() const;  // simulated time of the last frame
    const scene::MeshLibrary& meshes() const { return assets_->meshes(); }
    // "camera path (N keys, S s)", "replay (N ticks)" or "player view (no camera path)".
    std::string camera_description() const;
    const level::Level& level() const { return level_; }
    // The first tick at which a replay's recorded state hash differed from the simulated one:
    // the frames after it are not the game that was recorded.
    const std::optional<game::replay::Mismatch>& replay_mismatch() const { return mismatch_; }
    // Steps on, without drawing, to the replay's next recorded state hash (at most one hash
    // interval), so that the frames already taken are proven by a hash even when the run
    // stopped between two of them. Sets replay_mismatch() when that hash differs.
    void prove_replay();

  private:
    level::Level level_;
    std::unique_ptr<game::Assets> assets_;
    std::unique_ptr<game::World> world_;
    std::optional<game::replay::Player> player_;
    std::optional<game::replay::Mismatch> mismatch_;
    std::unique_ptr<scene::VectorFont> font_;
    double fov_;
    std::uint64_t ticks_ = 0;
};

}  // namespace bz::app
