#include "app/play_sessions.h"

#include <chrono>
#include <cstdio>
#include <utility>

#include "core/error.h"
#include "core/log.h"
#include "game/assets.h"
#include "game/backdrop.h"
#include "game/default_level.h"
#include "game/fixed_step.h"
#include "game/game.h"
#include "game/highscores.h"
#include "game/replay.h"
#include "platform/free_fly.h"

namespace bz::app {

namespace {

std::uint64_t clock_seed() {
    return static_cast<std::uint64_t>(std::chrono::system_clock::now().time_since_epoch().count());
}

// The game: screens, world, HUD, high scores and replays all live in game::Game; this turns
// input into its tick commands and its results into sounds and saved files.
class GameSession final : public PlaySession {
  public:
    GameSession(level::Level lvl, const SessionOptions& o, Log& log)
        : font_(o.font),
          high_scores_path_(o.high_scores),
          record_path_(o.record),
          pause_on_focus_loss_(o.pause_on_focus_loss),
          log_(log) {
        options_.seed = o.seed.value_or(clock_seed());
        game::HighScoreLoad scores = game::load_highscores(high_scores_path_);
        if (!scores.warning.empty()) log_.warn(scores.warning);
        options_.highscores = std::move(scores.table);
        options_.record = !record_path_.empty();
        // Recording starts a game at once rather than recording the title screen's wait.
        if (options_.record) options_.attract = false;
        game_ = std::make_unique<game::Game>(std::move(lvl), options_, font_);
        if (!o.replay.empty()) {
            game_->start_replay(game::replay::load(o.replay));
            log_.info("replaying " + o.replay);
        } else {
            log_.info("game seed " + std::to_string(options_.seed) + " (--seed repeats it)");
        }
    }

    ~GameSession() override {
        if (record_path_.empty()) return;
        try {
            if (const auto rec = game_->recording()) {
                game::replay::save(record_path_, *rec);
                log_.info("recorded " + std::to_string(rec->commands.size()) + " ticks to " +
                          record_path_);
            } else {
                log_.warn("nothing to record in " + record_path_ + ": no game was started");
            }
        } catch (const std::exception& e) {
            log_.error(std::string("cannot save the recording: ") + e.what());
        }
    }

    void tick(const platform::InputState& in) override {
        game::TickCommand cmd;
        cmd.left_tread = in.left_tread;
        cmd.right_tread = in.right_tread;
        cmd.fire = in.fire;
        cmd.up = in.up;
        cmd.down = in.down;
        cmd.left = in.left;
        cmd.right = in.right;
        // Presses last one tick, so a tap between two ticks is never lost and the game sees
        // the button go down and up again.
        cmd.pause = std::exchange(pause_, false);
        cmd.start = std::exchange(start_, false);
        cmd.back = std::exchange(back_, false);
        game_->tick(cmd);
        const game::SoundFrame& s = game_->sounds();
        engine_ = s.engine;
        for (const game::SoundEvent e : s.events) sounds_.push_back(e);
        if (game_->take_highscores_changed()) save_scores();
        report_replay_end();
    }

    void update(const platform::FlyControls&, double) override {}
    scene::FrameList frame(double alpha, double aspect) override {
        return game_->frame(alpha, aspect);
    }
    const scene::MeshLibrary& meshes() const override { return game_->meshes(); }

    SessionSounds take_sounds() override {
        SessionSounds out;
        const bool live = game_->screen() == game::Screen::playing;
        out.engine_on = live && engine_ > 0.0f;
        out.engine_speed = engine_;
        for (const game::SoundEvent e : sounds_) out.events.push_back(sound_cue(e));
        sounds_.clear();
        return out;
    }

    void on_action(platform::Action a) override {
        if (a == platform::Action::pause) pause_ = true;
        if (a == platform::Action::start) start_ = true;
        if (a == platform::Action::back) back_ = true;
    }

    void on_focus_lost() override {
        if (pause_on_focus_loss_ && game_->screen() == game::Screen::playing) pause_ = true;
    }

    void level_changed(const level::Level& lvl) override {
        if (game_->replaying()) {
            log_.warn("level changed during a replay; the replay keeps the level it started with");
            return;
        }
        // The game goes on in the edited level: score, lives, screen and the tank stay.
        const game::ReloadReport r = game_->reload_level(lvl);
        if (r.ended_recording) end_recording(*r.ended_recording);
        if (const game::World* w = game_->world()) {
            const glm::dvec3& at = w->state().player.body.transform.position;
            char where[64];
            std::snprintf(where, sizeof where, "(%.1f, %.1f)", at.x, at.z);
            log_.info(
                "level taken into the running game at tick " + std::to_string(w->state().tick) +
                ": score " + std::to_string(w->score()) + ", lives " + std::to_string(w->lives()) +
                ", tank at " + where +
                (r.world.player_moved ? " (moved out of an obstacle or onto the field)" : "") +
                (r.world.hostile_moved ? "; the enemy was moved to a free place" : ""));
        }
    }

    bool finished() const override { return game_->replay_finished(); }
    bool failed() const override { return game_->replay_mismatch().has_value(); }

  private:
    // A replay belongs to one level, so a reload ends the recording; saved now, and nothing
    // more is recorded this run.
    void end_recording(const game::replay::Replay& rec) {
        if (record_path_.empty()) return;
        const std::string path = std::exchange(record_path_, std::string());
        try {
            game::replay::save(path, rec);
            log_.info("the level changed, so the recording ends (a replay belongs to one level): " +
                      std::to_string(rec.commands.size()) + " ticks saved to " + path +
                      "; the rest of this run is not recorded");
        } catch (const std::exception& e) {
            log_.error(std::string("cannot save the recording: ") + e.what());
        }
    }

    void save_scores() {
        try {
            game::save_highscores(high_scores_path_, game_->highscores());
            log_.info("high scores saved: " + high_scores_path_.string());
        } catch (const UserError& e) {
            log_.warn(std::string("cannot save high scores: ") + e.what());
        }
    }

    void report_replay_end() {
        if (!game_->replaying() || replay_reported_) return;
        if (const auto& m = game_->replay_mismatch()) {
            log_.error("replay diverged at tick " + std::to_string(m->tick) + " (state hash " +
                       std::to_string(m->actual) + ", recorded " + std::to_string(m->expected) +
                       ")");
            replay_reported_ = true;
        } else if (game_->replay_finished()) {
            log_.info("replay finished; every recorded state hash matched");
            replay_reported_ = true;
        }
    }

    const scene::VectorFont* font_;
    std::filesystem::path high_scores_path_;
    std::string record_path_;
    bool pause_on_focus_loss_;
    Log& log_;
    game::GameOptions options_;
    std::unique_ptr<game::Game> game_;
    std::vector<game::SoundEvent> sounds_;
    float engine_ = 0.0f;
    bool pause_ = false, start_ = false, back_ = false;
    bool replay_reported_ = false;
};

// --edit: the level's objects and horizon from a free-flying camera; nothing moves but the
// volcano.
class EditSession final : public PlaySession {
  public:
    explicit EditSession(level::Level lvl)
        : level_(std::move(lvl)),
          assets_(std::make_unique<game::Assets>(level_)),
          camera_(level_.player_start + glm::dvec3(0.0, 6.0, 0.0), level_.player_heading_deg,
                  -10.0),
          obstacles_(build(level_)) {}

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
        const double seconds =
            (static_cast<double>(ticks_) + alpha) * game::FixedStep::kTickSeconds;
        game::backdrop::append_items(f.items, level_.backdrop, assets_->horizon(), f.camera.eye,
                                     seconds);
        return f;
    }

    const scene::MeshLibrary& meshes() const override { return assets_->meshes(); }
    SessionSounds take_sounds() override { return {}; }

    void level_changed(const level::Level& lvl) override {
        // The same assets, brought up to date (a changed horizon or model file too), so the
        // renderer keeps its cache. Checks and imports before anything changes.
        game::World::check_field(lvl);
        assets_->reload(lvl);
        obstacles_ = build(lvl);
        level_ = lvl;
    }

  private:
    // A world builds the obstacles through the factory table; its simulation never runs.
    std::vector<scene::Entity> build(const level::Level& lvl) const {
        return game::World(lvl, 0, assets_->factories(), assets_->models()).obstacles();
    }

    level::Level level_;
    std::unique_ptr<game::Assets> assets_;
    platform::FreeFlyCamera camera_;
    std::vector<scene::Entity> obstacles_;
    std::uint64_t ticks_ = 0;
};

level::Level chosen_level(const SessionOptions& o) {
    return o.level ? *o.level : game::default_level();
}

}  // namespace

SoundCue sound_cue(game::SoundEvent e) {
    using game::SoundEvent;
    using platform::Sound;
    switch (e) {
        case SoundEvent::shot:
            return {Sound::shot, 1.0f};
        case SoundEvent::enemy_shot:
            return {Sound::shot, 0.6f};
        case SoundEvent::explosion:
            return {Sound::explosion, 0.9f};
        case SoundEvent::shell_impact:
            return {Sound::explosion, 0.35f};
        case SoundEvent::player_death:
            return {Sound::explosion, 1.0f};
        case SoundEvent::radar_blip:
            return {Sound::radar_blip, 0.8f};
        case SoundEvent::warning:
            return {Sound::warning, 0.8f};
        case SoundEvent::bonus_life:
            return {Sound::radar_blip, 1.0f};
        case SoundEvent::blocked:
            return {Sound::warning, 0.3f};
    }
    return {Sound::radar_blip, 0.0f};
}

std::unique_ptr<PlaySession> make_game_session(const SessionOptions& o, Log& log) {
    return std::make_unique<GameSession>(chosen_level(o), o, log);
}

std::unique_ptr<PlaySession> make_edit_session(const SessionOptions& o, Log&) {
    return std::make_unique<EditSession>(chosen_level(o));
}

}  // namespace bz::app
