#include "app/play_sessions.h"

#include <chrono>
#include <cmath>
#include <numbers>

#include "core/log.h"
#include "game/assets.h"
#include "game/backdrop.h"
#include "game/default_level.h"
#include "game/fixed_step.h"
#include "game/world.h"
#include "platform/free_fly.h"

namespace bz::app {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

std::uint64_t clock_seed() {
    return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count());
}

// The game: World ticks from the player's input, sounds out, frames in.
class GameSession final : public PlaySession {
public:
    GameSession(level::Level lvl, std::uint64_t seed, Log& log)
        : level_(std::move(lvl)), seed_(seed), assets_(level_.backdrop), log_(log) {
        world_ = std::make_unique<game::World>(level_, seed_, assets_.factories(), assets_.models());
        log_.info("game seed " + std::to_string(seed_));
    }

    void tick(const platform::InputState& in) override {
        game::TickCommand cmd;
        cmd.left_tread = in.left_tread;
        cmd.right_tread = in.right_tread;
        cmd.fire = in.fire;
        world_->step(cmd);
        ++ticks_;
        for (const game::SoundEvent e : world_->events()) events_.push_back(e);
    }

    void update(const platform::FlyControls&, double) override {}

    scene::FrameList frame(double alpha, double aspect) override {
        (void)aspect;
        scene::FrameList f = world_->interpolated_frame(alpha);
        const double seconds = (static_cast<double>(ticks_) + alpha) * game::FixedStep::kTickSeconds;
        game::backdrop::append_items(f.items, level_.backdrop, assets_.horizon(), f.camera.eye, seconds);
        return f;
    }

    const scene::MeshLibrary& meshes() const override { return assets_.meshes(); }

    SessionSounds take_sounds() override {
        SessionSounds s;
        s.engine_speed = world_->engine_level();
        s.engine_on = s.engine_speed > 0.0f;
        for (const game::SoundEvent e : events_) s.events.push_back(sound_cue(e));
        events_.clear();
        return s;
    }

    void level_changed(const level::Level& lvl) override {
        // Same assets (so mesh ids stay valid for the renderer's cache), a new world from the
        // new level, with the tank where it was.
        level::Level next = lvl;
        const scene::Transform& t = world_->state().player.body.transform;
        next.player_start = {t.position.x, 0.0, t.position.z};
        next.player_heading_deg = t.yaw * kRadToDeg;
        auto world = std::make_unique<game::World>(next, seed_, assets_.factories(), assets_.models());
        world_ = std::move(world);
        level_ = std::move(next);
    }

private:
    level::Level level_;
    std::uint64_t seed_;
    game::Assets assets_;
    Log& log_;
    std::unique_ptr<game::World> world_;
    std::vector<game::SoundEvent> events_;
    std::uint64_t ticks_ = 0;
};

// --edit: the level's objects and horizon from a free-flying camera; nothing moves.
class EditSession final : public PlaySession {
public:
    explicit EditSession(level::Level lvl)
        : level_(std::move(lvl)),
          assets_(level_.backdrop),
          camera_(level_.player_start + glm::dvec3(0.0, 6.0, 0.0), level_.player_heading_deg, -10.0) {
        rebuild();
    }

    void tick(const platform::InputState&) override { ++ticks_; }
    void update(const platform::FlyControls& fly, double dt) override { camera_.update(fly, dt); }

    scene::FrameList frame(double alpha, double) override {
        scene::FrameList f;
        f.camera.eye = camera_.position();
        f.camera.target = camera_.target();
        f.camera.fov_y_deg = 60.0;
        f.camera.near = 0.3;
        f.camera.far = 5000.0;
        for (const scene::Entity& e : obstacles_) {
            scene::DrawItem item;
            item.mesh = e.mesh;
            item.model = e.transform.matrix();
            item.color = e.color;
            f.items.push_back(item);
        }
        const double seconds = (static_cast<double>(ticks_) + alpha) * game::FixedStep::kTickSeconds;
        game::backdrop::append_items(f.items, level_.backdrop, assets_.horizon(), f.camera.eye, seconds);
        return f;
    }

    const scene::MeshLibrary& meshes() const override { return assets_.meshes(); }
    SessionSounds take_sounds() override { return {}; }

    void level_changed(const level::Level& lvl) override {
        level_ = lvl;
        rebuild();
    }

private:
    void rebuild() {
        // The world builds the obstacles through the factory table; its simulation never runs.
        const game::World world(level_, 0, assets_.factories(), assets_.models());
        obstacles_ = world.obstacles();
    }

    level::Level level_;
    game::Assets assets_;
    platform::FreeFlyCamera camera_;
    std::vector<scene::Entity> obstacles_;
    std::uint64_t ticks_ = 0;
};

level::Level chosen_level(const SessionOptions& o) { return o.level ? *o.level : game::default_level(); }

}  // namespace

SoundCue sound_cue(game::SoundEvent e) {
    using game::SoundEvent;
    using platform::Sound;
    switch (e) {
        case SoundEvent::shot: return {Sound::shot, 1.0f};
        case SoundEvent::enemy_shot: return {Sound::shot, 0.6f};
        case SoundEvent::explosion: return {Sound::explosion, 0.9f};
        case SoundEvent::shell_impact: return {Sound::explosion, 0.35f};
        case SoundEvent::player_death: return {Sound::explosion, 1.0f};
        case SoundEvent::radar_blip: return {Sound::radar_blip, 0.8f};
        case SoundEvent::warning: return {Sound::warning, 0.8f};
        case SoundEvent::bonus_life: return {Sound::radar_blip, 1.0f};
        case SoundEvent::blocked: return {Sound::warning, 0.3f};
    }
    return {Sound::radar_blip, 0.0f};
}

std::unique_ptr<PlaySession> make_game_session(const SessionOptions& o, Log& log) {
    return std::make_unique<GameSession>(chosen_level(o), o.seed.value_or(clock_seed()), log);
}

std::unique_ptr<PlaySession> make_edit_session(const SessionOptions& o, Log&) {
    return std::make_unique<EditSession>(chosen_level(o));
}

}  // namespace bz::app
