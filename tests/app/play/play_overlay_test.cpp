#include "app/play/play_overlay.h"

#include <gtest/gtest.h>

#include "app/play/edit_footer.h"
#include "game/hud/hud_layout.h"
#include "support/default_font.h"

namespace bz::app {
namespace {

namespace hud = game::hud;

bool all_in(const std::vector<scene::HudLine>& lines, const hud::Box& box) {
    for (const scene::HudLine& l : lines) {
        if (!box.contains(l.a) || !box.contains(l.b)) {
            ADD_FAILURE() << "line (" << l.a.x << ", " << l.a.y << ") - (" << l.b.x << ", " << l.b.y
                          << ") outside [" << box.min.x << ", " << box.min.y << "] - [" << box.max.x
                          << ", " << box.max.y << "]";
            return false;
        }
    }
    return true;
}

const std::string kLongModelError =
    "levels/classic.toml:42:11: error: model 'data/models/broken_tank_with_a_long_name.obj' "
    "cannot be used: Assimp: OBJ: vertex index out of range on line 1234 of the file, and "
    "the rest of this sentence is here only to make it wrap over several lines of the box";

TEST(PlayOverlay, ErrorsWrapInsideTheirBoxAndSayTheirKind) {
    for (const double aspect : {4.0 / 3.0, 16.0 / 9.0}) {
        PlayOverlay o(bz::test::default_font());
        o.set_errors(ErrorKind::model, {kLongModelError});
        const auto lines = o.error_box_lines(aspect);
        ASSERT_GE(lines.size(), 3u);
        EXPECT_TRUE(lines[0].title);
        EXPECT_EQ(lines[0].text.rfind("MODEL ERROR", 0), 0u);
        std::vector<scene::HudLine> out;
        o.draw(out, aspect);
        ASSERT_FALSE(out.empty());
        EXPECT_TRUE(all_in(out, hud::error_box(static_cast<float>(aspect))));
    }
}

TEST(PlayOverlay, EachKindIsNamed) {
    PlayOverlay o(bz::test::default_font());
    o.set_errors(ErrorKind::shader, {"shaders/lines/lines.frag:3:1: error: syntax"});
    o.set_errors(ErrorKind::settings, {"settings.toml:1:10: error: volume must be ..."});
    const auto lines = o.error_box_lines(16.0 / 9.0);
    std::vector<std::string> titles;
    for (const auto& l : lines) {
        if (l.title) titles.push_back(l.text.substr(0, l.text.find(" - ")));
    }
    EXPECT_EQ(titles, (std::vector<std::string>{"SHADER ERROR", "SETTINGS ERROR"}));
    o.set_errors(ErrorKind::level, {"a.toml:1:1: error: x"});
    EXPECT_EQ(o.error_box_lines(16.0 / 9.0).front().text.rfind("LEVEL ERROR", 0), 0u);
    EXPECT_EQ(o.errors().size(), 3u);
}

TEST(PlayOverlay, ManyErrorsKeepTheFirstLinesAndCountTheRest) {
    PlayOverlay o(bz::test::default_font());
    std::vector<std::string> errors;
    for (int i = 1; i <= 30; ++i) {
        errors.push_back("level.toml:" + std::to_string(i) + ":1: error: number " +
                         std::to_string(i));
    }
    o.set_errors(ErrorKind::level, errors);
    const auto lines = o.error_box_lines(16.0 / 9.0);
    ASSERT_GE(lines.size(), 3u);
    EXPECT_LT(lines.size(), 12u);
    EXPECT_EQ(lines[1].text, "level.toml:1:1: error: number 1");  // the first is kept
    EXPECT_EQ(lines.back().text.rfind("... ", 0), 0u);
    EXPECT_NE(lines.back().text.find("more lines in beamzone.log"), std::string::npos);
    std::vector<scene::HudLine> out;
    o.draw(out, 16.0 / 9.0);
    EXPECT_TRUE(all_in(out, hud::error_box(16.0f / 9.0f)));
}

TEST(PlayOverlay, TimedErrorsGoAway) {
    PlayOverlay o(bz::test::default_font());
    o.set_errors(ErrorKind::settings, {"bad"}, 1.0);
    o.advance(0.5);
    EXPECT_EQ(o.errors(ErrorKind::settings).size(), 1u);
    o.advance(0.6);
    EXPECT_TRUE(o.errors(ErrorKind::settings).empty());
}

TEST(PlayOverlay, NoticesAndFooterStayInTheirRegions) {
    PlayOverlay o(bz::test::default_font());
    for (int i = 0; i < 6; ++i) o.notify("screenshot screenshot-000" + std::to_string(i) + ".png");
    o.set_footer("60 FPS  16.7 MS  WORST 18.0 MS");
    std::vector<scene::HudLine> out;
    o.draw(out, 16.0 / 9.0);
    ASSERT_FALSE(out.empty());
    const float a = 16.0f / 9.0f;
    for (const scene::HudLine& l : out) {
        const bool ok = (hud::notice_box(a).contains(l.a) && hud::notice_box(a).contains(l.b)) ||
                        (hud::readout_box(a).contains(l.a) && hud::readout_box(a).contains(l.b));
        EXPECT_TRUE(ok) << l.a.x << "," << l.a.y;
    }
}

}  // namespace
}  // namespace bz::app

namespace bz::app {
namespace {

// The height of the strokes in `lines` that lie inside `box`.
float height_in(const std::vector<scene::HudLine>& lines, const hud::Box& box) {
    float lo = 1e9f, hi = -1e9f;
    for (const scene::HudLine& l : lines) {
        if (!box.contains(l.a) || !box.contains(l.b)) continue;
        lo = std::min({lo, l.a.y, l.b.y});
        hi = std::max({hi, l.a.y, l.b.y});
    }
    return hi > lo ? hi - lo : 0.0f;
}

// The player's text size (Comfort page) reaches the overlay: at 2x the notice, the frame-rate
// readout and the error box draw twice as tall as at 1x, each still inside its own region
// (which for the readout strip and the notices grows with the text).
TEST(PlayOverlay, TextFollowsTheTextSizeAndStaysInItsRegions) {
    for (const double aspect : {4.0 / 3.0, 16.0 / 9.0}) {
        const auto a = static_cast<float>(aspect);
        float notice[2] = {}, readout[2] = {}, error[2] = {};
        for (const int i : {0, 1}) {
            const float scale = i == 0 ? 1.0f : 2.0f;
            PlayOverlay o(bz::test::default_font());
            o.set_text_scale(scale);
            o.notify("VOLUME 80");
            o.set_footer("60 FPS 16.7 MS");
            o.set_errors(ErrorKind::shader, {"LINES.GLSL 3 SYNTAX"});
            std::vector<scene::HudLine> out;
            o.draw(out, aspect);
            for (const scene::HudLine& l : out) {
                const bool in =
                    (hud::notice_box(a, scale).contains(l.a) &&
                     hud::notice_box(a, scale).contains(l.b)) ||
                    (hud::readout_box(a, scale).contains(l.a) &&
                     hud::readout_box(a, scale).contains(l.b)) ||
                    (hud::error_box(a).contains(l.a) && hud::error_box(a).contains(l.b));
                EXPECT_TRUE(in) << "scale " << scale << ": " << l.a.x << "," << l.a.y;
            }
            notice[i] = height_in(out, hud::notice_box(a, scale));
            readout[i] = height_in(out, hud::readout_box(a, scale));
            error[i] = height_in(out, hud::error_box(a));
        }
        EXPECT_NEAR(notice[1] / notice[0], 2.0f, 0.05f);
        EXPECT_NEAR(error[1] / error[0], 2.0f, 0.3f);  // title and line, with the gap between
        EXPECT_GT(readout[1] / readout[0], 1.9f);
    }
}

// The --edit screen at every text size 1x to 2x and every window shape from 800x600 to
// 3840x2160 (and a 21:9 one): both footer lines follow the text size (breaking onto more lines
// rather than shrinking when too wide), stay on the screen inside the footer, and the frame-rate
// readout and the notices stack above the footer in their own regions.
TEST(PlayOverlay, EditFooterFollowsTheTextSizeAndTheReadoutKeepsItsOwnRegion) {
    const std::string status =
        "X -123.4  Y 12.0  Z 456.7   HEADING 359   PITCH -45   AIM: ARCADE_NARROW_PYRAMID  "
        "battlefield_1980.toml:123";
    const std::pair<int, int> windows[] = {{800, 600},   {1024, 768},  {1280, 800},
                                           {1920, 1080}, {2560, 1080}, {3840, 2160}};
    for (const auto& [w, h] : windows) {
        const double aspect = static_cast<double>(w) / h;
        const auto a = static_cast<float>(aspect);
        float keys_height_1x = 0.0f;
        for (const float scale : {1.0f, 1.25f, 1.5f, 1.75f, 2.0f}) {
            SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " at " +
                         std::to_string(scale));
            const EditFooter footer =
                layout_edit_footer(bz::test::default_font(), status, kEditKeyHints, aspect, scale);
            std::vector<scene::HudLine> drawn;
            draw_edit_footer(bz::test::default_font(), footer, drawn);
            ASSERT_FALSE(drawn.empty());
            EXPECT_TRUE(all_in(drawn, footer.box));
            EXPECT_TRUE(all_in(drawn, {{-a, -1.0f}, {a, 1.0f}})) << "on the screen";
            EXPECT_GE(footer.box.max.y, hud::kFooterTop);
            // Every word of both lines is there, in order, and each line's text follows the
            // scale unless one piece alone is wider than the screen.
            std::string keys_back, status_back;
            for (auto it = footer.lines.rbegin(); it != footer.lines.rend(); ++it) {
                std::string& to = it->status ? status_back : keys_back;
                to += (to.empty() ? "" : "   ") + it->text;
                const float base = it->status ? kEditStatusHeight : kEditKeysHeight;
                if (it->height < base * scale - 1e-6f) {
                    EXPECT_NEAR(bz::test::default_font().width(it->text, it->height),
                                footer.box.width(), 1e-4f)
                        << "shrunk only to fit: " << it->text;
                } else {
                    EXPECT_NEAR(it->height, base * scale, 1e-6f) << it->text;
                }
                if (!it->status && scale == 1.0f) keys_height_1x = it->height;
                if (!it->status && scale == 2.0f && keys_height_1x > 0.0f) {
                    EXPECT_NEAR(it->height / keys_height_1x, 2.0f, 0.01f) << it->text;
                }
            }
            EXPECT_EQ(keys_back, kEditKeyHints);
            EXPECT_EQ(status_back, status);

            // The overlay over it: readout and notice in their regions, above the footer.
            PlayOverlay o(bz::test::default_font());
            o.set_text_scale(scale);
            o.set_footer_top(footer.box.max.y);
            o.set_footer("60 FPS 16.7 MS");
            o.notify("SCREENSHOT SAVED");
            std::vector<scene::HudLine> over;
            o.draw(over, aspect);
            const hud::Box readout = hud::readout_box(a, scale, footer.box.max.y);
            const hud::Box notice = hud::notice_box(a, scale, footer.box.max.y);
            EXPECT_GT(readout.min.y, footer.box.max.y) << "the readout never covers the footer";
            EXPECT_GT(notice.min.y, readout.max.y);
            EXPECT_LE(notice.max.y, hud::kEditNoticeTop);
            EXPECT_LT(notice.max.y, -0.03f) << "under the centre cross";
            EXPECT_GT(height_in(over, readout), 0.0f) << "the readout is drawn";
            EXPECT_GT(height_in(over, notice), 0.0f) << "the notice is drawn";
            for (const scene::HudLine& l : over) {
                const bool in = (readout.contains(l.a) && readout.contains(l.b)) ||
                                (notice.contains(l.a) && notice.contains(l.b));
                EXPECT_TRUE(in) << l.a.x << "," << l.a.y;
            }
        }
    }
}

}  // namespace
}  // namespace bz::app
