#include "app/play/menu/menu_page.h"

#include <algorithm>

#include "game/hud/hud_layout.h"

namespace bz::app::menu {

namespace {

namespace hud = game::hud;
using scene::TextAlign;

const glm::vec3 kTitleColor = hud::kRed;
const glm::vec3 kRowColor = hud::kGreen;
const glm::vec3 kSelectedColor = hud::kWhite;
const glm::vec3 kWarnColor = hud::kRed;
const glm::vec3 kHintColor{0.55f, 0.85f, 0.6f};

constexpr float kHintHeight = 0.036f;
constexpr float kLineHeight = 0.04f;

Layout layout_for(const Page& page, float scale) {
    Layout l;
    // The title's rows sit low on the dark ground, below the band around the horizon where the
    // attract demo's obstacles, tanks and wreckage stand: from -0.06 down, the first rows were
    // drawn across them (the pyramid through START).
    if (page.big_title) {
        l.rows_top = -0.32f;
        l.row_step = 0.09f;
        l.rows_bottom = -0.78f;
    }
    if (page.under_band) {  // under the reticle too, on the ground
        l.title_y = -0.32f;
        l.rows_top = -0.46f;
        l.row_step = 0.09f;
        l.rows_bottom = -0.8f;
    }
    if (page.columns) {
        l.row_height = 0.042f;
        l.row_step = 0.072f;
    }
    if (!page.lines.empty()) {
        // Room for the lines under the rows, at their own size, above the hint.
        const auto n = static_cast<float>(page.lines.size());
        l.rows_bottom = std::max(l.rows_bottom, -0.84f + n * kLineHeight * 1.6f * scale + 0.04f);
    }
    l.row_height *= scale;
    l.row_step *= scale;
    // The last row stays above the frame-rate readout's strip, which grows with the text.
    l.rows_bottom =
        std::max(l.rows_bottom, hud::readout_box(1.0f, scale).max.y + 0.4f * l.row_height);
    // Larger text: when the rows no longer fit, they may rise towards the title (the demo's
    // band on the title screen is less important than reading the menu), then they scroll.
    const std::size_t n = page.rows.size();
    const float wanted = l.rows_bottom + l.row_step * static_cast<float>(n > 0 ? n - 1 : 0);
    const float ceiling = page.big_title    ? 0.22f
                          : page.under_band ? l.title_y - 0.1f * scale
                                            : l.title_y - 0.12f * scale;
    if (wanted > l.rows_top) l.rows_top = std::min(wanted, std::max(ceiling, l.rows_top));
    // The pause menu under the band: at a large text size its title rises with its rows (over
    // the paused view) rather than leave room for only two rows.
    if (page.under_band && wanted > l.rows_top) {
        const float band_floor = hud::kBandBottom - 0.06f - 0.1f * scale;
        l.rows_top = std::min(wanted, std::max(band_floor - 0.1f * scale, l.rows_top));
        l.title_y = std::max(l.title_y, l.rows_top + 0.1f * scale);
    }
    return l;
}

}  // namespace

Window scroll_window(std::size_t rows, std::size_t selected, std::size_t visible) {
    Window w;
    w.count = std::min(rows, std::max<std::size_t>(visible, 1));
    if (rows <= w.count) return w;
    // Keep the selection in the middle of the window where the list allows it.
    const std::size_t half = w.count / 2;
    const std::size_t first = selected > half ? selected - half : 0;
    w.first = std::min(first, rows - w.count);
    return w;
}

Placement place(const scene::VectorFont& font, const Page& page, std::size_t selected,
                double aspect, float scale) {
    const float a = static_cast<float>(aspect);
    Placement pl;
    pl.layout = layout_for(page, scale);
    const Layout& l = pl.layout;
    const auto visible = static_cast<std::size_t>((l.rows_top - l.rows_bottom) / l.row_step) + 1;
    pl.window = scroll_window(page.rows.size(), selected, visible);
    // Columns as wide as their widest entry, the table centred; a table wider than the
    // screen gets smaller text.
    float h = l.row_height;
    float label_w = 0.0f, value_w = 0.0f, note_w = 0.0f;
    for (const Row& r : page.rows) {
        label_w = std::max(label_w, font.width(r.label, h));
        value_w = std::max(value_w, font.width(r.choice ? "< " + r.value + " >" : r.value, h));
        note_w = std::max(note_w, font.width(r.note, h * 0.85f));
    }
    const float gap = 0.12f * scale;
    float table_w = label_w + gap + value_w + (note_w > 0.0f ? gap + note_w : 0.0f);
    const float room = 2.0f * a - 0.3f;
    float shrink = 1.0f;
    if (page.columns && table_w > room) {
        shrink = room / table_w;
        h *= shrink;
        table_w = room;
    }
    pl.text_height = h;
    pl.label_x = -0.5f * table_w;
    pl.value_x = pl.label_x + (label_w + gap) * shrink;
    pl.note_x = pl.value_x + (value_w + gap) * shrink;
    float y = l.rows_top;
    for (std::size_t i = pl.window.first; i < pl.window.first + pl.window.count;
         ++i, y -= l.row_step) {
        const Row& r = page.rows[i];
        float x0 = pl.label_x, x1 = pl.label_x + table_w;
        float row_h = h;
        if (!page.columns) {
            std::string text = r.label;
            if (!r.value.empty()) text += "   < " + r.value + " >";
            // A centred row wider than the screen (a long level name beside LEVEL) gets
            // smaller text, leaving room for the selection marks either side.
            const float row_room = room - 2.0f * (0.08f * scale + h);
            const float w = font.width(text, h);
            if (w > row_room) row_h = h * row_room / w;
            const float half = font.width(text, row_h) * 0.5f;
            x0 = -half;
            x1 = half;
        }
        // The row's box reaches half a step either side of its text, so the rows tile.
        const float pad = 0.1f * scale;
        pl.rows.push_back(
            {i,
             y,
             {{x0 - pad, y - 0.5f * (l.row_step - h)}, {x1 + pad, y + h + 0.5f * (l.row_step - h)}},
             row_h});
    }
    pl.after_rows_y = y;
    return pl;
}

std::optional<std::size_t> row_at(const Placement& placement, const Page& page, glm::vec2 at) {
    for (const PlacedRow& r : placement.rows) {
        if (r.row < page.rows.size() && page.rows[r.row].selectable && r.box.contains(at, 0.0f)) {
            return r.row;
        }
    }
    return std::nullopt;
}

void draw(std::vector<scene::HudLine>& out, const scene::VectorFont& font, const Page& page,
          std::size_t selected, double aspect, std::uint64_t tick, float scale, FooterLine footer) {
    const float a = static_cast<float>(aspect);
    const Placement pl = place(font, page, selected, aspect, scale);
    const Layout& l = pl.layout;
    const float title_scale = std::min(scale, 1.5f);  // the title is large already
    if (page.big_title) {
        font.draw(out, page.title, {0.0f, 0.5f}, 0.2f, kTitleColor, TextAlign::center, 1.4f);
        font.draw(out, "A VECTOR TANK BATTLE", {0.0f, 0.34f}, 0.05f * title_scale, kRowColor,
                  TextAlign::center);
    } else {
        font.draw(out, page.title, {0.0f, l.title_y}, 0.09f * title_scale, kTitleColor,
                  TextAlign::center, 1.2f);
    }
    const float h = pl.text_height;
    const bool blink_on = (tick / 20) % 3 != 0;
    for (const PlacedRow& placed : pl.rows) {
        const std::size_t i = placed.row;
        const float y = placed.y;
        const Row& r = page.rows[i];
        const bool sel = i == selected && r.selectable;
        const glm::vec3 color = sel ? kSelectedColor : kRowColor;
        const float glow = sel ? 1.5f : 0.9f;
        if (!page.columns) {
            const float rh = placed.text_height;
            std::string text = r.label;
            if (!r.value.empty())
                text += "   " + (sel && r.choice ? "< " + r.value + " >" : r.value);
            font.draw(out, text, {0.0f, y}, rh, color, TextAlign::center, glow);
            if (sel && blink_on) {
                const float half = font.width(text, rh) * 0.5f + 0.08f * scale;
                font.draw(out, ">", {-half, y}, rh, kSelectedColor, TextAlign::right, 1.5f);
                font.draw(out, "<", {half, y}, rh, kSelectedColor, TextAlign::left, 1.5f);
            }
            continue;
        }
        if (sel && blink_on) {
            font.draw(out, ">", {pl.label_x - 0.05f * scale, y}, h, kSelectedColor,
                      TextAlign::right, 1.5f);
        }
        font.draw(out, r.label, {pl.label_x, y}, h, color, TextAlign::left, glow);
        const glm::vec3 vcolor = r.warn ? kWarnColor : color;
        std::string value = r.value;
        if (sel && r.choice) value = "< " + value + " >";
        font.draw(out, value, {pl.value_x, y}, h, vcolor, TextAlign::left, glow);
        if (!r.note.empty()) {
            font.draw(out, r.note, {pl.note_x, y}, h * 0.85f, r.warn ? kWarnColor : kHintColor,
                      TextAlign::left, glow);
        }
    }
    const float more_h = 0.03f * scale;
    if (pl.window.first > 0) {
        font.draw(out, "MORE ABOVE", {pl.label_x, l.rows_top + l.row_step * 0.7f}, more_h,
                  kHintColor);
    }
    const float y = pl.after_rows_y;
    if (pl.window.first + pl.window.count < page.rows.size()) {
        font.draw(out, "MORE BELOW", {pl.label_x, y + l.row_step * 0.3f}, more_h, kHintColor);
    }

    const float line_h = kLineHeight * scale;
    float ly = std::min(y, l.rows_bottom) - 0.04f;
    for (const std::string& line : page.lines) {
        // A line wider than the screen gets smaller text.
        float lh = line_h;
        const float wdt = font.width(line, lh);
        if (wdt > 2.0f * a - 0.2f) lh *= (2.0f * a - 0.2f) / wdt;
        font.draw(out, line, {0.0f, ly}, lh, kWarnColor, TextAlign::center, 1.2f);
        ly -= line_h * 1.6f;
    }

    if (footer == FooterLine::hints && !page.hint.empty()) {
        const hud::Box f = hud::footer_box(a);
        // Long hints shrink to the footer's width rather than run off the screen.
        float hint_h = kHintHeight * scale;
        const float wdt = font.width(page.hint, hint_h);
        if (wdt > f.width()) hint_h *= f.width() / wdt;
        hint_h = std::min(hint_h, f.max.y - f.min.y);
        font.draw(out, page.hint, {0.0f, f.min.y + 0.4f * hint_h}, hint_h, kHintColor,
                  TextAlign::center);
    }
}

}  // namespace bz::app::menu
