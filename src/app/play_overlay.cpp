#include "app/play_overlay.h"

#include <algorithm>

namespace bz::app {

namespace {

constexpr float kMargin = 0.05f;
constexpr float kErrorHeight = 0.04f;
constexpr float kNoticeHeight = 0.045f;
constexpr float kLineGap = 1.6f;  // baseline to baseline, in text heights
constexpr std::size_t kMaxErrorLines = 14;
const glm::vec3 kErrorColor{1.0f, 0.25f, 0.2f};
const glm::vec3 kNoticeColor{0.4f, 1.0f, 0.5f};

}  // namespace

void PlayOverlay::notify(std::string text, double seconds) {
    notices_.push_back({std::move(text), seconds});
    if (notices_.size() > 4) notices_.erase(notices_.begin());
}

void PlayOverlay::advance(double seconds) {
    for (auto& n : notices_) n.seconds_left -= seconds;
    std::erase_if(notices_, [](const Notice& n) { return n.seconds_left <= 0.0; });
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

void PlayOverlay::draw(std::vector<scene::HudLine>& out, double aspect) const {
    const float a = static_cast<float>(aspect);
    const float max_width = 2.0f * a - 2.0f * kMargin;
    if (!errors_.empty()) {
        std::vector<std::string> lines;
        for (const auto& e : errors_) {
            for (auto& l : wrap(e, kErrorHeight, max_width)) lines.push_back(std::move(l));
        }
        if (lines.size() > kMaxErrorLines) {
            const std::size_t hidden = lines.size() - (kMaxErrorLines - 1);
            lines.resize(kMaxErrorLines - 1);
            lines.push_back("... and " + std::to_string(hidden) + " more lines (see the log)");
        }
        float y = 1.0f - kMargin - kErrorHeight;
        font_.draw(out, "LEVEL ERROR - still playing the last good version", {-a + kMargin, y},
                   kErrorHeight * 1.2f, kErrorColor);
        y -= kErrorHeight * kLineGap * 1.2f;
        for (const auto& l : lines) {
            font_.draw(out, l, {-a + kMargin, y}, kErrorHeight, kErrorColor);
            y -= kErrorHeight * kLineGap;
        }
    }
    float y = -1.0f + kMargin;
    for (auto it = notices_.rbegin(); it != notices_.rend(); ++it) {
        const float fade = static_cast<float>(std::clamp(it->seconds_left / 0.5, 0.0, 1.0));
        const auto lines = wrap(it->text, kNoticeHeight, max_width);
        for (auto l = lines.rbegin(); l != lines.rend(); ++l) {  // drawn bottom-up
            font_.draw(out, *l, {-a + kMargin, y}, kNoticeHeight, kNoticeColor,
                       scene::TextAlign::left, fade);
            y += kNoticeHeight * kLineGap;
        }
    }
}

}  // namespace bz::app
