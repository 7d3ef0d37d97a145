#include "app/play/play_overlay.h"

#include <algorithm>

#include "app/play/text_band.h"
#include "game/hud/hud_layout.h"

namespace bz::app {

namespace {

namespace hud = game::hud;

constexpr float kErrorHeight = 0.034f;
constexpr float kErrorTitleHeight = 0.04f;
constexpr float kNoticeHeight = 0.042f;
constexpr float kFooterHeight = 0.036f;
constexpr float kLineGap = 1.55f;  // baseline to baseline, in text heights
const glm::vec3 kErrorColor{1.0f, 0.25f, 0.2f};
const glm::vec3 kNoticeColor{0.4f, 1.0f, 0.5f};
const glm::vec3 kFooterColor{0.6f, 0.9f, 0.7f};

}  // namespace

std::string_view error_title(ErrorKind kind) {
    switch (kind) {
        case ErrorKind::level:
            return "LEVEL ERROR - still playing the last good version";
        case ErrorKind::model:
            return "MODEL ERROR - still playing the last good version";
        case ErrorKind::shader:
            return "SHADER ERROR - keeping the old shaders";
        case ErrorKind::settings:
            return "SETTINGS ERROR - using defaults for these";
        case ErrorKind::count:
            break;
    }
    return "ERROR";
}

void PlayOverlay::set_errors(ErrorKind kind, std::vector<std::string> lines,
                             std::optional<double> seconds) {
    Errors& e = errors_.at(static_cast<std::size_t>(kind));
    e.lines = std::move(lines);
    e.seconds_left = seconds;
}

const std::vector<std::string>& PlayOverlay::errors(ErrorKind kind) const {
    return errors_.at(static_cast<std::size_t>(kind)).lines;
}

std::vector<std::string> PlayOverlay::errors() const {
    std::vector<std::string> all;
    for (const Errors& e : errors_) all.insert(all.end(), e.lines.begin(), e.lines.end());
    return all;
}

void PlayOverlay::notify(std::string text, double seconds) {
    notices_.push_back({std::move(text), seconds});
    if (notices_.size() > 4) notices_.erase(notices_.begin());
}

void PlayOverlay::advance(double seconds) {
    for (auto& n : notices_) n.seconds_left -= seconds;
    std::erase_if(notices_, [](const Notice& n) { return n.seconds_left <= 0.0; });
    for (Errors& e : errors_) {
        if (!e.seconds_left) continue;
        *e.seconds_left -= seconds;
        if (*e.seconds_left <= 0.0) e = {};
    }
}

std::vector<std::string> PlayOverlay::wrap(const std::string& text, float height,
                                           float max_width) const {
    std::vector<std::string> lines;
    std::string rest = text;
    while (!rest.empty()) {
        if (font_.width(rest, height) <= max_width) {
            lines.push_back(rest);
            break;
        }
        // Longest prefix that fits, then back off to the last space in it.
        std::size_t fit = 1;
        while (fit < rest.size() &&
               font_.width(std::string_view(rest).substr(0, fit + 1), height) <= max_width) {
            ++fit;
        }
        const std::size_t space = rest.rfind(' ', fit);
        const std::size_t cut = space != std::string::npos && space > 0 ? space : fit;
        lines.push_back(rest.substr(0, cut));
        rest.erase(0, cut);
        while (!rest.empty() && rest.front() == ' ') rest.erase(0, 1);
    }
    return lines;
}

std::vector<PlayOverlay::BoxLine> PlayOverlay::error_box_lines(double aspect) const {
    const hud::Box box = hud::error_box(static_cast<float>(aspect));
    std::vector<BoxLine> all;
    for (std::size_t k = 0; k < errors_.size(); ++k) {
        if (errors_[k].lines.empty()) continue;
        all.push_back({std::string(error_title(static_cast<ErrorKind>(k))), true});
        for (const auto& e : errors_[k].lines) {
            for (auto& l : wrap(e, kErrorHeight * scale_, box.width()))
                all.push_back({std::move(l)});
        }
    }
    // As many lines as the box holds: the first ones (the first error is the one to fix
    // first), then a count of the rest, which the log has in full.
    const float title_step = kErrorTitleHeight * scale_ * kLineGap;
    const float step = kErrorHeight * scale_ * kLineGap;
    float used = 0.0f;
    std::size_t fits = 0;
    for (const BoxLine& l : all) {
        const float h = l.title ? title_step : step;
        if (used + h > box.height() + 1e-4f) break;
        used += h;
        ++fits;
    }
    if (fits < all.size()) {
        const std::size_t kept = fits > 1 ? fits - 1 : 0;  // room for the count line
        const std::size_t hidden = all.size() - kept;
        all.resize(kept);
        all.push_back({"... " + std::to_string(hidden) + " more lines in beamzone.log"});
    }
    return all;
}

void PlayOverlay::draw(std::vector<scene::HudLine>& out, double aspect) const {
    const float a = static_cast<float>(aspect);
    const hud::Box ebox = hud::error_box(a);
    float y = ebox.max.y;
    for (const BoxLine& l : error_box_lines(aspect)) {
        float h = (l.title ? kErrorTitleHeight : kErrorHeight) * scale_;
        y -= h * kLineGap;
        // A title is one line: at a large text size a long one gets smaller to fit the box.
        if (const float w = font_.width(l.text, h); l.title && w > ebox.width())
            h *= ebox.width() / w;
        font_.draw(out, l.text, {ebox.min.x, y + h * kBaselineLift}, h, kErrorColor,
                   scene::TextAlign::left, l.title ? 1.2f : 1.0f);
    }

    if (notice_in_footer()) {
        // One line, centred as the menu's hints are; a long one gets smaller to fit.
        const Notice& n = notices_.back();
        const float fade = static_cast<float>(std::clamp(n.seconds_left / 0.5, 0.0, 1.0));
        const hud::Box f = hud::footer_box(a);
        float h = std::min(kNoticeHeight * scale_, f.height() / kTextBand);
        if (const float w = font_.width(n.text, h); w > f.width()) h *= f.width() / w;
        font_.draw(out, n.text, {0.0f, f.min.y + h * kBaselineLift}, h, kNoticeColor,
                   scene::TextAlign::center, fade);
    }
    const hud::Box nbox = hud::notice_box(a, scale_, footer_top_);
    const float nh = kNoticeHeight * scale_;
    y = nbox.min.y + nh * kBaselineLift;
    for (auto it = notices_.rbegin(); it != notices_.rend() && !notice_in_footer(); ++it) {
        const float fade = static_cast<float>(std::clamp(it->seconds_left / 0.5, 0.0, 1.0));
        const auto lines = wrap(it->text, nh, nbox.width());
        for (auto l = lines.rbegin(); l != lines.rend(); ++l) {  // drawn bottom-up
            // Full: the oldest go unshown.
            if (y + nh * (1.0f + kGlyphOvershoot) > nbox.max.y) break;
            font_.draw(out, *l, {nbox.min.x, y}, nh, kNoticeColor, scene::TextAlign::left, fade);
            y += nh * kLineGap;
        }
    }

    if (!footer_.empty()) {
        const hud::Box rbox = hud::readout_box(a, scale_, footer_top_);
        // The strip is one line high at any text size (hud::readout_box grows with it).
        const float fh = std::min(kFooterHeight * scale_, rbox.height() / kTextBand);
        font_.draw(out, footer_, {rbox.max.x, rbox.min.y + fh * kBaselineLift}, fh, kFooterColor,
                   scene::TextAlign::right, 0.8f);
    }
}

}  // namespace bz::app
