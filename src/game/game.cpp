#include "game/game.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "core/error.h"
#include "core/text/ascii_case.h"
#include "game/assets/backdrop.h"
#include "game/default_level.h"
#include "game/difficulty/autopilot.h"
#include "game/difficulty/difficulty.h"
#include "game/hud/hud.h"
#include "game/hud/hud_layout.h"
#include "game/hud/screens.h"
#include "game/world/tuning.h"

namespace bz::game {

namespace {

constexpr int kGameOverTicks = 4 * tuning::kTicksPerSecond;
constexpr int kTableTicks = 8 * tuning::kTicksPerSecond;
constexpr int kAttractCycleTicks = 10 * tuning::kTicksPerSecond;
constexpr int kInitialsTimeoutTicks = 60 * tuning::kTicksPerSecond;
constexpr std::string_view kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 ";
constexpr std::uint64_t kDemoSeed = 0xDE30;

char cycle(char c, int by) {
    const std::size_t n = kAlphabet.size();
    std::size_t i = kAlphabet.find(c);
    if (i == std::string_view::npos) i = 0;
    return kAlphabet[(i + n + static_cast<std::size_t>(by + static_cast<int>(n))) % n];
}

}  // namespace

// Buttons that went down this tick, and menu up/down from keys or treads.
struct Game::Buttons {
    std::uint8_t pressed = 0;
    int vertical = 0;  // +1 up, -1 down, on the tick it starts
    bool is(std::uint8_t b) const { return (pressed & b) != 0; }
};

Game::Game(level::Level level, GameOptions options, const scene::VectorFont* font)
    : level_(std::move(level)),
      options_(std::move(options)),
      font_(font),
      assets_(std::make_unique<Assets>(level_)),
      highscores_(options_.highscores) {
    // Build the level once up front so a bad object kind or model fails here, not mid-game.
    demo_ = std::make_unique<World>(playing_level(level_), kDemoSeed, assets_->factories(),
                                    assets_->models(), 3);
    if (!options_.attract) start_game();
}

Game::~Game() = default;

std::string Game::highscores_title() const {
    std::string title = level_key(level_.name, 0).name;
    title = ascii_upper(std::move(title));
    // Tables are kept apart by the rules played; the non-default ones are named.
    if (options_.arcade.any()) title += " (" + arcade_label(options_.arcade) + ")";
    return title;
}

std::string Game::level_name() const {
    if (!options_.level_name.empty()) return options_.level_name;
    if (level_.file.empty() || level_.file == kBuiltinLevelName) return kBuiltinLevelName;
    return level_.file.string();
}

level::Difficulty Game::difficulty() const {
    return options_.difficulty.value_or(level_.enemies.difficulty);
}

level::Level Game::playing_level(const level::Level& level) const {
    return with_arcade_rules(
        level_for(level, options_.difficulty.value_or(level.enemies.difficulty)), options_.arcade);
}

int Game::start_lives() const {
    return options_.lives > 0 ? options_.lives
                              : options_.arcade.lives.value_or(level_.player_lives);
}

void Game::set_rules(std::optional<level::Difficulty> difficulty, const ArcadeRules& arcade) {
    if (difficulty == options_.difficulty && arcade == options_.arcade) return;
    options_.difficulty = difficulty;
    options_.arcade = arcade;
    demo_->reload_level(playing_level(level_), assets_->factories());
}

std::uint64_t Game::level_hash_value() const {
    if (!level_hash_) level_hash_ = replay::level_hash(level_);
    return *level_hash_;
}

void Game::start_game() {
    const std::uint64_t seed = options_.seed + games_started_++;
    world_ = std::make_unique<World>(playing_level(level_), seed, assets_->factories(),
                                     assets_->models(), start_lives());
    playback_.reset();
    mismatch_.reset();
    recorder_.reset();
    if (options_.record) {
        replay::Header h;
        h.seed = seed;
        h.level = level_name();
        h.level_hash = level_hash_value();
        h.lives = start_lives();
        h.difficulty = difficulty();
        h.missile_score = options_.arcade.missile_score;
        h.bonus_score = options_.arcade.bonus_score;
        h.missile_nastier_after = world_->rules().missile_nastier_after;
        h.hash_interval = std::max(1, options_.hash_interval);
        recorder_.emplace(std::move(h));
    }
    screen_ = Screen::playing;
    screen_ticks_ = 0;
}

void Game::resume() {
    if (screen_ == Screen::paused) screen_ = Screen::playing;
}

bool Game::score_qualifies() const {
    return world_ && !playback_ && highscores_.qualifies(world_->score());
}

void Game::quit_to_title() {
    const bool enter =
        (screen_ == Screen::playing || screen_ == Screen::paused) && score_qualifies();
    if (recorder_ && world_) ended_recording_ = recorder_->finish(*world_);
    recorder_.reset();
    playback_.reset();
    screen_ticks_ = 0;
    if (enter) {
        new_rank_ = -1;
        screen_ = Screen::enter_initials;
        initials_.clear();
        initial_ = 'A';
        return;
    }
    screen_ = Screen::attract;
}

void Game::start_replay(replay::Replay r) {
    if (r.header.level_hash != level_hash_value()) {
        throw UserError("the replay was recorded on a different level (" + r.header.level +
                        ", hash " + std::to_string(r.header.level_hash) +
                        ") than the one loaded (" + level_name() + ", hash " +
                        std::to_string(level_hash_value()) + ")");
    }
    world_ = std::make_unique<World>(replay::played_level(r.header, level_), r.header.seed,
                                     assets_->factories(), assets_->models(), r.header.lives);
    recorder_.reset();
    mismatch_.reset();
    playback_.emplace(std::move(r));
    screen_ = Screen::playing;
    screen_ticks_ = 0;
}

std::optional<replay::Replay> Game::recording() const {
    if (!recorder_ || !world_) return ended_recording_;
    return recorder_->finish(*world_);
}

ReloadReport Game::reload_level(const level::Level& level) {
    if (playback_) {
        throw UserError("the level changed during a replay; a replay keeps its own level");
    }
    // Everything that can fail is checked before anything changes: the field, the kinds and
    // the models here, and then both worlds build the same obstacles from the same factories.
    World::check_field(level);
    assets_->reload(level);
    demo_->reload_level(playing_level(level), assets_->factories());
    ReloadReport report;
    if (recorder_ && world_) {
        report.ended_recording = recorder_->finish(*world_);
        ended_recording_ = report.ended_recording;
        recorder_.reset();
        options_.record = false;
    }
    if (world_) report.world = world_->reload_level(playing_level(level), assets_->factories());
    level_ = level;
    level_hash_.reset();
    return report;
}

bool Game::take_highscores_changed() {
    const bool changed = highscores_changed_;
    highscores_changed_ = false;
    return changed;
}

void Game::end_game() {
    screen_ = Screen::game_over;
    screen_ticks_ = 0;
}

void Game::step_world(const TickCommand& command) {
    if (playback_) {
        if (playback_->done()) {
            end_game();
            return;
        }
        world_->step(playback_->next());
        if (auto m = playback_->check(*world_)) {
            mismatch_ = m;
            end_game();
        }
    } else {
        world_->step(command);
        if (recorder_) recorder_->record(command, *world_);
    }
    sounds_.engine = world_->engine_level();
    sounds_.events = world_->events();
    if (world_->game_over()) end_game();
}

void Game::step_demo() {
    if (!demo_ || demo_->game_over()) {
        demo_ = std::make_unique<World>(playing_level(level_), kDemoSeed + ++demo_games_,
                                        assets_->factories(), assets_->models(), 3);
    }
    demo_->step(autopilot(*demo_));
}

void Game::step_initials(const Buttons& b) {
    if (b.vertical != 0) initial_ = cycle(initial_, b.vertical);
    if (b.is(button::back) || b.is(button::left)) {
        if (!initials_.empty()) {
            initial_ = initials_.back();
            initials_.pop_back();
        }
    } else if (b.is(button::fire) || b.is(button::start) || b.is(button::right)) {
        initials_ += initial_;
        initial_ = 'A';
    }
    if (initials_.size() < HighScoreTable::kInitials && screen_ticks_ < kInitialsTimeoutTicks)
        return;
    // Done (or the player walked away): file the entry.
    std::string name = initials_;
    if (name.size() < HighScoreTable::kInitials) name += initial_;
    const auto rank = highscores_.insert({name, world_ ? world_->score() : 0});
    new_rank_ = rank ? static_cast<int>(*rank) : -1;
    highscores_changed_ = rank.has_value();
    screen_ = Screen::high_scores;
    screen_ticks_ = 0;
}

void Game::tick(const TickCommand& command) {
    const PackedCommand packed = pack(command);
    Buttons b;
    b.pressed = static_cast<std::uint8_t>(packed.buttons & ~prev_buttons_);
    prev_buttons_ = packed.buttons;
    int vertical = command.up ? 1 : (command.down ? -1 : 0);
    const float treads = command.left_tread + command.right_tread;
    if (vertical == 0) vertical = treads > 1.2f ? 1 : (treads < -1.2f ? -1 : 0);
    b.vertical = vertical != prev_vertical_ ? vertical : 0;
    prev_vertical_ = vertical;

    ++ticks_;
    ++screen_ticks_;
    sounds_.engine = 0.0f;
    sounds_.events.clear();

    switch (screen_) {
        case Screen::attract:
            step_demo();
            if (b.is(button::start) || b.is(button::fire)) start_game();
            break;
        case Screen::playing:
            if (b.is(button::pause)) {
                screen_ = Screen::paused;
                break;
            }
            step_world(command);
            break;
        case Screen::paused:
            if (b.is(button::pause) || b.is(button::start)) {
                screen_ = Screen::playing;
            } else if (b.is(button::back)) {
                end_game();
            }
            break;
        case Screen::game_over:
            step_demo();
            if (screen_ticks_ >= kGameOverTicks ||
                (screen_ticks_ > tuning::kTicksPerSecond && b.is(button::start))) {
                const int score = world_ ? world_->score() : 0;
                screen_ticks_ = 0;
                new_rank_ = -1;
                if (!playback_ && highscores_.qualifies(score)) {
                    screen_ = Screen::enter_initials;
                    initials_.clear();
                    initial_ = 'A';
                } else {
                    screen_ = playback_ ? Screen::attract : Screen::high_scores;
                }
            }
            break;
        case Screen::enter_initials:
            step_demo();
            step_initials(b);
            break;
        case Screen::high_scores:
            step_demo();
            if (b.is(button::start)) {
                start_game();
            } else if (screen_ticks_ >= kTableTicks) {
                screen_ = Screen::attract;
                screen_ticks_ = 0;
            }
            break;
    }
}

bool Game::shows_live_world() const {
    return world_ && (screen_ == Screen::playing || screen_ == Screen::paused ||
                      screen_ == Screen::game_over);
}

scene::FrameList Game::frame(double alpha, double aspect) const {
    const bool live = shows_live_world();
    const World& shown = live ? *world_ : *demo_;
    const double a = screen_ == Screen::paused ? 1.0 : alpha;
    scene::FrameList f = shown.interpolated_frame(a, options_.fov_y_deg);
    // The play HUD's band is the radar strip; the scene (sky included) stays under it.
    if (live) f.view_top = hud::kBandBottom;
    const double seconds = (static_cast<double>(ticks_) + a) / tuning::kTicksPerSecond;
    f.time_s = seconds;  // phosphor decay and frame holding follow game time
    f.seed = static_cast<std::uint32_t>(ticks_);
    backdrop::append_items(f.items, level_.backdrop, assets_->horizon(), f.camera.eye, seconds);
    if (screen_ == Screen::enter_initials || screen_ == Screen::high_scores) {
        f.items.clear();  // text only: the table must be readable
    } else if (!live) {
        for (scene::DrawItem& item : f.items) item.intensity *= 0.55f;
    }

    hud::View view;
    view.alpha = a;
    view.aspect = aspect;
    view.fov_y_deg = options_.fov_y_deg;
    view.high_score = highscores_.best();
    view.font = font_;
    view.text_scale = options_.text_scale;
    switch (screen_) {
        case Screen::attract:
            if (options_.app_menus) break;  // the app's title menu is drawn over the demo
            if ((ticks_ / kAttractCycleTicks) % 2 == 0) {
                screens::title(f.hud, font_, aspect, ticks_, highscores_.best(),
                               options_.hints.title);
            } else {
                screens::high_scores(f.hud, font_, highscores_, -1, ticks_);
            }
            break;
        case Screen::playing:
            hud::play_hud(f.hud, *world_, view);
            break;
        case Screen::paused:
            hud::play_hud(f.hud, *world_, view);
            if (!options_.app_menus) screens::paused(f.hud, font_, options_.hints.paused);
            break;
        case Screen::game_over:
            hud::status(f.hud, *world_, view);
            screens::game_over(f.hud, font_, world_->score());
            break;
        case Screen::enter_initials:
            screens::enter_initials(f.hud, font_, initials_, initial_, world_ ? world_->score() : 0,
                                    ticks_, options_.hints.initials);
            break;
        case Screen::high_scores:
            screens::high_scores(f.hud, font_, highscores_, new_rank_, ticks_);
            break;
    }
    // Tables are kept per level: say whose this is.
    if (screen_ == Screen::high_scores || (screen_ == Screen::attract && !options_.app_menus &&
                                           (ticks_ / kAttractCycleTicks) % 2 == 1)) {
        hud::text(f.hud, font_, highscores_title(), {0.0f, 0.54f}, 0.045f, hud::kGreen,
                  scene::TextAlign::center);
    }
    if (playback_ && live) {
        std::string note;
        if (mismatch_) note = "DIVERGED AT TICK " + std::to_string(mismatch_->tick);
        screens::replay_banner(f.hud, font_, aspect, note);
    }
    return f;
}

}  // namespace bz::game
