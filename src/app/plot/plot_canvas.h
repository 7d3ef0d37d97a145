#pragma once
// A tiny rasteriser for benchmark plots: filled rectangles, anti-aliased lines and stroke
// text (Hershey font through scene::VectorFont) on an RGB image, saved with bz::write_png.
// Coordinates are pixels with y up from the bottom-left, like the rest of the renderer.
#include <filesystem>
#include <glm/glm.hpp>
#include <string_view>

#include "core/image_io.h"
#include "scene/vector_font.h"

namespace bz::app {

class Canvas {
  public:
    // `font` may be null: text is then left out.
    Canvas(int width, int height, glm::vec3 background, const scene::VectorFont* font);

    void fill_rect(glm::vec2 lo, glm::vec2 hi, glm::vec3 color);
    // A line of the given width (pixels) with soft edges.
    void line(glm::vec2 a, glm::vec2 b, glm::vec3 color, float width = 1.0f);
    void disc(glm::vec2 centre, float radius, glm::vec3 color);
    // Text with its baseline at `origin`, cap height `height` pixels. `vertical` turns it a
    // quarter turn anticlockwise (for a y-axis label).
    void text(std::string_view s, glm::vec2 origin, float height, glm::vec3 color,
              scene::TextAlign align = scene::TextAlign::left, bool vertical = false);
    float text_width(std::string_view s, float height) const;

    int width() const { return width_; }
    int height() const { return height_; }
    const Image& image() const { return image_; }
    void save(const std::filesystem::path& path) const;  // atomic; throws UserError

  private:
    void blend(int x, int y, glm::vec3 color, float alpha);
    int width_;
    int height_;
    Image image_;
    const scene::VectorFont* font_;
};

}  // namespace bz::app
