#include "app/play/play_sessions.h"

#include <chrono>
#include <cstdio>
#include <utility>

#include "app/play/edit_footer.h"
#include "app/play/edit_status.h"
#include "core/error.h"
#include "core/log.h"
#include "game/assets/assets.h"
#include "game/assets/backdrop.h"
#include "game/default_level.h"
#include "game/difficulty/difficulty.h"
#include "game/fixed_step.h"
#include "game/game.h"
#include "game/hud/hud_layout.h"
#include "game/records/highscores.h"
#include "game/records/level_rules.h"
#include "game/records/replay.h"
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
        options_.difficulty = game::parse_difficulty(o.difficulty);
        options_.arcade = o.arcade;
        game::HighScoreLoad scores = game::load_highscores(high_scores_path_);
        for (const std::string& e : scores.errors) log_.warn(e);
        if (!scores.message.empty()) {
            log_.warn(scores.message);
            notices_.push_back(scores.message);
        }
        scores_may_save_ = scores.may_save;
        book_ = std::move(scores.book);
        key_ = key_of(lvl);
        options_.highscores = book_.table(key_);
        options_.record = !record_path_.empty();
        options_.app_menus = o.app_menus;
        options_.hints = o.hints;
        // Recording starts a game at once rather than recording the title screen's wait.
        if (options_.record) options_.attract = false;
        game_ = std::make_unique<game::Game>(std::move(lvl), options_, font_);
        if (!o.replay.empty()) {
            game_->start_replay(game::replay::load(o.replay));
            log_.info("replaying " + o.replay);
        } else {
            log_.info("game seed " + std::to_string(options_.seed) + " (--seed repeats it), " +
                      std::string(game::difficulty_name(game_->difficulty())) + " difficulty");
        }
    }

    // A run cut short by an exception still keeps its recording.
    ~GameSession() override { save_on_exit(); }

    bool save_on_exit() override {
        if (record_path_.empty()) return !save_failed_;
        const std::string path = std::exchange(record_path_, std::string());
        try {
            if (const auto rec = game_->recording()) {
                game::replay::save(path, *rec);
                log_.info("recorded " + std::to_string(rec->commands.size()) + " ticks to " + path);
            } else {
                log_.warn("nothing to record in " + path + ": no game was started");
            }
        } catch (const std::exception& e) {
            log_.error(std::string("cannot save the recording: ") + e.what());
            save_failed_ = true;
        }
        return !save_failed_;
    }

    void tick(const platform::InputState& in) override {
        apply_pending_rules();
        game::TickCommand cmd;
        if (menu_context() != menu::Context::none) {
            // A menu has the keys: the game under it only animates (the demo runs on).
            pause_ = start_ = back_ = false;
            game_->tick(cmd);
            collect_results();
            return;
        }
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
        collect_results();
    }

    menu::Context menu_context() const override {
        if (!options_.app_menus) return menu::Context::none;
        if (game_->screen() == game::Screen::attract) return menu::Context::title;
        if (game_->screen() == game::Screen::paused) return menu::Context::paused;
        return menu::Context::none;
    }

    void menu_command(MenuCommand c) override {
        switch (c) {
            case MenuCommand::start_game:
                apply_pending_rules();
                if (game_->screen() == game::Screen::attract) game_->start_game();
                break;
            case MenuCommand::resume:
                game_->resume();
                break;
            case MenuCommand::quit_to_title:
                game_->quit_to_title();
                break;
        }
    }

    void rules_changed(const std::string& difficulty, const game::ArcadeRules& arcade) override {
        pending_rules_ = PendingRules{game::parse_difficulty(difficulty), arcade};
        apply_pending_rules();
    }

    int score_at_stake() const override {
        const bool in_game =
            game_->screen() == game::Screen::playing || game_->screen() == game::Screen::paused;
        return in_game && game_->world() && !game_->replaying() ? game_->world()->score() : 0;
    }
    bool score_qualifies() const override { return game_->score_qualifies(); }

    const game::HighScoreTable* high_scores() const override { return &game_->highscores(); }
    std::string high_scores_level() const override { return game_->highscores_title(); }
    void set_text_scale(float scale) override { game_->set_text_scale(scale); }
    void keys_changed(const platform::Bindings& keys) override {
        game_->set_hints(screen_hints(keys));
    }

    void collect_results() {
        const game::SoundFrame& s = game_->sounds();
        engine_ = s.engine;
        for (const game::SoundEvent e : s.events) sounds_.push_back(e);
        if (game_->take_highscores_changed()) save_scores();
        report_replay_end();
    }

    void update(const platform::FlyControls&, double) override {}
    // A frame after a level reload, or whose camera cut between the demo's tank and the
    // player's, has no past: the renderer forgets the phosphor trails (FrameList::cut).
    scene::FrameList frame(double alpha, double aspect) override {
        scene::FrameList f = game_->frame(alpha, aspect);
        const bool live = game_->shows_live_world();
        f.cut = std::exchange(cut_, false) || live != std::exchange(shown_live_, live);
        return f;
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
        cut_ = true;
        if (r.ended_recording) end_recording(*r.ended_recording);
        // Edited rules make another table (high scores are kept per level and rules).
        if (const game::LevelKey key = key_of(lvl); key != key_) {
            key_ = key;
            game_->set_highscores(book_.table(key_));
        }
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

    std::vector<std::string> take_notices() override { return std::exchange(notices_, {}); }

    // A replay that diverged ends the run (exit 1), as `replay --verify` and `bench --replay`
    // do: what would follow is no longer the recorded game.
    bool finished() const override {
        return game_->replay_finished() || game_->replay_mismatch().has_value() ||
               PlaySession::finished();
    }
    bool failed() const override { return game_->replay_mismatch().has_value(); }

  private:
    // New rules wait for the title screen: the game in play (or paused) keeps the rules it
    // began with, and its score goes into the table of those rules.
    void apply_pending_rules() {
        if (!pending_rules_ || game_->screen() != game::Screen::attract || game_->replaying()) {
            return;
        }
        options_.difficulty = pending_rules_->difficulty;
        options_.arcade = pending_rules_->arcade;
        pending_rules_.reset();
        game_->set_rules(options_.difficulty, options_.arcade);
        if (const game::LevelKey key = key_of(game_->level()); key != key_) {
            key_ = key;
            game_->set_highscores(book_.table(key_));
        }
    }

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
            save_failed_ = true;
        }
    }

    // Scores compare only within one level played at one difficulty and one set of arcade
    // settings: the key hashes the rules as played.
    game::LevelKey key_of(const level::Level& lvl) const {
        const level::Difficulty d = options_.difficulty.value_or(lvl.enemies.difficulty);
        return game::level_key(lvl.name, game::level_rules_hash(game::with_arcade_rules(
                                             game::level_for(lvl, d), options_.arcade)));
    }

    void save_scores() {
        book_.set(key_, game_->highscores());
        if (!scores_may_save_) {
            log_.warn("not saving high scores: " + high_scores_path_.string() +
                      " is damaged and could not be moved aside");
            return;
        }
        try {
            game::save_highscores(high_scores_path_, book_);
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
    // The next frame cuts (a level reload); whether the last frame showed the live world.
    bool cut_ = false, shown_live_ = false;
    bool replay_reported_ = false;
    bool save_failed_ = false;
    game::HighScoreBook book_;  // every level's table; the game shows key_'s
    game::LevelKey key_;
    bool scores_may_save_ = true;
    struct PendingRules {
        std::optional<level::Difficulty> difficulty;
        game::ArcadeRules arcade;
    };
    std::optional<PendingRules> pending_rules_;
    std::vector<std::string> notices_;
};

// --edit: the level's objects and horizon from a free-flying camera; nothing moves but the
// volcano.
class EditSession final : public PlaySession {
  public:
    EditSession(level::Level lvl, const scene::VectorFont* font)
        : font_(font),
          level_(std::move(lvl)),
          assets_(std::make_unique<game::Assets>(level_)),
          camera_(level_.player_start + glm::dvec3(0.0, 6.0, 0.0), level_.player_heading_deg,
                  -10.0),
          obstacles_(build(level_)) {}

    void tick(const platform::InputState&) override { ++ticks_; }
    void update(const platform::FlyControls& fly, double dt) override { camera_.update(fly, dt); }
    // An editor shows the level as it is now: no phosphor trails of where the camera was.
    void set_text_scale(float scale) override { text_scale_ = scale; }
    bool keeps_history() const override { return false; }
    float footer_top() const override { return footer_top_; }

    scene::FrameList frame(double alpha, double aspect) override {
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
        draw_status(f.hud, aspect);
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
    // Where the camera is and what it looks at, the reticle, and the keys, in the footer.
    void draw_status(std::vector<scene::HudLine>& out, double aspect) const {
        namespace hud = game::hud;
        constexpr float s = 0.03f;  // a small cross: the point the status line names
        out.push_back({{-s, 0.0f}, {s, 0.0f}, hud::kWhite, 0.8f});
        out.push_back({{0.0f, -s}, {0.0f, s}, hud::kWhite, 0.8f});
        if (!font_) return;
        const std::string status = edit_status_line(level_, camera_.position(), camera_.yaw_deg(),
                                                    camera_.pitch_deg(), camera_.forward());
        // Both lines follow the player's text size, breaking onto more lines when too wide.
        const EditFooter footer =
            layout_edit_footer(*font_, status, kEditKeyHints, aspect, text_scale_);
        draw_edit_footer(*font_, footer, out);
        footer_top_ = footer.box.max.y;
        const hud::Box f = footer.box;
        auto fit = [&](const std::string& text, float h) {
            const float w = font_->width(text, h);
            return w > f.width() ? h * f.width() / w : h;
        };
        const std::string title = "EDIT  " + level_.file.filename().string();
        const float title_h = fit(title, 0.04f * text_scale_);
        font_->draw(out, title, {f.max.x, 0.96f - title_h * 1.15f}, title_h, hud::kRed,
                    scene::TextAlign::right);
    }

    // A world builds the obstacles through the factory table; its simulation never runs.
    std::vector<scene::Entity> build(const level::Level& lvl) const {
        return game::World(lvl, 0, assets_->factories(), assets_->models()).obstacles();
    }

    float text_scale_ = 1.0f;
    mutable float footer_top_ = game::hud::kFooterTop;  // of the last frame's footer
    const scene::VectorFont* font_;
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

game::ArcadeRules arcade_rules(const platform::ArcadeDips& dips) {
    game::ArcadeRules r;
    r.lives = dips.lives;
    r.missile_score = dips.missile_score;
    r.bonus_score = dips.bonus_score;
    return r;
}

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

game::screens::Hints screen_hints(const platform::Bindings& keys) {
    using platform::Action;
    using platform::keys_label;
    game::screens::Hints h;
    h.initials = keys_label(keys, Action::drive_forward, 1) + " / " +
                 keys_label(keys, Action::drive_back, 1) + " CHOOSE   " +
                 keys_label(keys, Action::fire, 1) + " NEXT   " +
                 keys_label(keys, Action::back, 1) + " ERASE";
    h.paused = keys_label(keys, Action::pause) + " RESUME   " + keys_label(keys, Action::back, 1) +
               " QUIT";
    h.title = keys_label(keys, Action::start, 1) + " START";
    return h;
}

std::unique_ptr<PlaySession> make_game_session(const SessionOptions& o, Log& log) {
    return std::make_unique<GameSession>(chosen_level(o), o, log);
}

std::unique_ptr<PlaySession> make_edit_session(const SessionOptions& o, Log&) {
    return std::make_unique<EditSession>(chosen_level(o), o.font);
}

}  // namespace bz::app
