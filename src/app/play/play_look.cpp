#include "app/play/play_look.h"

#include <cstdio>

namespace bz::app {

namespace {

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace

PlayLook choose_look(const LookSources& s, const level::Level* level) {
    const level::RenderSettings* lv = level ? &level->render : nullptr;
    std::string style, style_from, preset, preset_from;
    if (s.cli_style) {
        style = *s.cli_style;
        style_from = "command line";
    } else if (lv && lv->style_given) {
        style = lv->style;
        style_from = "level";
    } else {
        style = s.settings_style;
        style_from = s.settings_style_given ? "settings file" : "default";
    }
    if (s.cli_preset) {
        preset = *s.cli_preset;
        preset_from = "command line";
    } else if (s.settings_preset) {
        preset = *s.settings_preset;
        preset_from = "settings file";
    } else if (lv && lv->preset_given) {
        preset = lv->preset;
        preset_from = "level";
    } else {
        preset = render::RenderSettings{}.preset;
        preset_from = "default";
    }

    std::string beam(render::kDefaultBeamLook), beam_from = "default";
    if (s.cli_beam) {
        beam = *s.cli_beam;
        beam_from = "command line";
    } else if (s.settings_beam) {
        beam = *s.settings_beam;
        beam_from = "settings file";
    } else if (lv && lv->beam) {
        beam = *lv->beam;
        beam_from = "level";
    }

    PlayLook look;
    look.style = scene::style_from_name(style).value_or(scene::Style::vector);
    look.render = render::preset(preset);
    look.render.beam = render::beam_look(beam);
    look.render.beam.overlay = s.settings_overlay || (lv && lv->overlay.value_or(false));
    // Battlezone's vector generator redrew at about 41 Hz.
    look.render.beam.refresh_hz =
        s.settings_hold_41hz || (lv && lv->hold_41hz.value_or(false)) ? 41.0f : 0.0f;
    // The canonical name, whatever alias the level or the settings file used ("occluded").
    look.summary = "style " + std::string(scene::style_name(look.style)) + " (" + style_from +
                   "), preset " + preset + " (" + preset_from + "), beam " + beam + " (" +
                   beam_from + ")";
    if (s.flashes == "soft") {
        look.render.beam.flicker *= 0.5f;
        look.render.beam.persistence_ms *= 0.5f;
        look.summary += ", flicker and trails halved (settings file)";
    } else if (s.flashes == "off") {
        look.render.beam.flicker = 0.0f;
        look.render.beam.phosphor = render::PhosphorDecay::off;
        look.summary += ", no flicker or trails (settings file)";
    }
    look.render.beam.colour_safe = s.colour_safe;
    if (look.render.beam.overlay)
        look.summary += s.colour_safe ? ", colour-safe overlay" : ", overlay";
    if (look.render.beam.refresh_hz > 0.0f) look.summary += ", 41 Hz hold";
    const std::optional<std::string>& method =
        s.cli_line_method
            ? s.cli_line_method
            : (s.settings_line_method ? s.settings_line_method
                                      : (lv ? lv->line_method : std::optional<std::string>{}));
    if (method) {
        look.render.method = render::parse_line_method(*method);
        look.summary += std::string(", line method ") +
                        render::line_method_name(look.render.method) + " (" +
                        (s.cli_line_method        ? "command line"
                         : s.settings_line_method ? "settings file"
                                                  : "level") +
                        ")";
    }
    if (!lv) return look;
    if (lv->line_width_px) {
        look.render.line_half_width_px = static_cast<float>(*lv->line_width_px * 0.5);
        look.summary += ", line width " + number(*lv->line_width_px) + " px (level)";
    }
    if (lv->crease_angle_deg) {
        look.render.crease_angle_deg = static_cast<float>(*lv->crease_angle_deg);
        look.summary += ", crease angle " + number(*lv->crease_angle_deg) + " deg (level)";
    }
    if (lv->bloom_strength) {
        look.render.bloom_strength = static_cast<float>(*lv->bloom_strength);
        look.summary += ", bloom strength " + number(*lv->bloom_strength) + " (level)";
    }
    if (lv->material_lines) {
        look.render.material_lines = *lv->material_lines;
        look.summary +=
            std::string(", material lines ") + (*lv->material_lines ? "on" : "off") + " (level)";
    }
    if (lv->intersection_lines) {
        look.render.intersection_lines = *lv->intersection_lines;
        look.summary += std::string(", intersection lines ") +
                        (*lv->intersection_lines ? "on" : "off") + " (level)";
    }
    return look;
}

}  // namespace bz::app
