#include "app/play/edit_footer.h"

#include <algorithm>
#include <string_view>

#include "app/play/text_band.h"

namespace bz::app {

namespace {

namespace hud = game::hud;

constexpr std::string_view kGap = "   ";

// Splits at the "   " gaps into as few lines as fit `width` at `height` (greedy, in order).
std::vector<std::string> break_at_gaps(const scene::VectorFont& font, const std::string& text,
                                       float height, float width) {
    std::vector<std::string> pieces;
    for (std::size_t at = 0;;) {
        const std::size_t gap = text.find(kGap, at);
        pieces.push_back(text.substr(at, gap == std::string::npos ? std::string::npos : gap - at));
        if (gap == std::string::npos) break;
        at = text.find_first_not_of(' ', gap);
        if (at == std::string::npos) break;
    }
    std::vector<std::string> lines;
    for (std::string& p : pieces) {
        if (!lines.empty()) {
            const std::string joined = lines.back() + std::string(kGap) + p;
            if (font.width(joined, height) <= width) {
                lines.back() = joined;
                continue;
            }
        }
        lines.push_back(std::move(p));
    }
    return lines;
}

}  // namespace

EditFooter layout_edit_footer(const scene::VectorFont& font, const std::string& status,
                              const std::string& keys, double aspect, float text_scale) {
    const float a = static_cast<float>(aspect);
    const float s = std::clamp(text_scale, 1.0f, 2.0f);
    const hud::Box one_line = hud::footer_box(a);
    EditFooter f;
    f.box = {one_line.min, {one_line.max.x, one_line.min.y}};
    float y = one_line.min.y;  // bottom of the next band
    auto stack = [&](const std::string& text, float base_height, bool is_status) {
        const float width = f.box.width();
        const std::vector<std::string> lines = break_at_gaps(font, text, base_height * s, width);
        for (auto it = lines.rbegin(); it != lines.rend(); ++it) {  // bottom-up
            float h = base_height * s;
            if (const float w = font.width(*it, h); w > width) h *= width / w;
            f.lines.push_back({*it, {f.box.min.x, y + h * kBaselineLift}, h, is_status});
            y += h * kTextBand;
        }
    };
    stack(keys, kEditKeysHeight, false);
    stack(status, kEditStatusHeight, true);
    f.box.max.y = std::max(y, one_line.max.y);  // never lower than the one-line footer
    return f;
}

void draw_edit_footer(const scene::VectorFont& font, const EditFooter& footer,
                      std::vector<scene::HudLine>& out) {
    for (const EditFooterLine& l : footer.lines) {
        font.draw(out, l.text, l.origin, l.height, l.status ? hud::kGreen : hud::kWhite,
                  scene::TextAlign::left, l.status ? 1.1f : 0.8f);
    }
}

}  // namespace bz::app
