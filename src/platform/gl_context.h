#pragma once
// An SDL window with an OpenGL 4.5 core context, or a hidden one for headless work
// (SDL_VIDEODRIVER=offscreen gives an EGL context on Mesa llvmpipe with no display).
#include <memory>
#include <string>

#include "gl/debug.h"

struct SDL_Window;

namespace bz::platform {

enum class WindowMode { hidden, windowed, fullscreen_desktop };
enum class Vsync { off, on, adaptive };

struct ContextOptions {
    WindowMode mode = WindowMode::hidden;
    int width = 1280;
    int height = 720;
    std::string title = "beamzone";
    bool debug = true;
};

class GlContext {
  public:
    // Throws UserError with a one-line reason when no GL 4.5 context can be had.
    explicit GlContext(const ContextOptions& options);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    SDL_Window* window() const { return window_; }
    gl::DebugSink& debug() { return *debug_; }
    std::string renderer_name() const;
    bool is_software() const;  // llvmpipe / softpipe: timer queries miss geometry work
    void drawable_size(int& w, int& h) const;
    void swap();
    // Returns the mode actually set (adaptive falls back to on when the driver refuses).
    Vsync set_vsync(Vsync v);
    // Borderless fullscreen on the window's display, and back to the window it was. Under X11
    // this moves and resizes a borderless window itself rather than asking the window manager:
    // without one (Xvfb, kiosks) SDL's request changes only SDL's idea of the size, and a
    // display-sized frame was drawn into the unchanged window.
    void set_fullscreen(bool on);
    bool fullscreen() const;

  private:
    struct WindowedPlace {
        int x = 0, y = 0, w = 0, h = 0;
    };
    SDL_Window* window_ = nullptr;
    bool resize_for_fullscreen_ = false;  // the X11 way above
    bool resized_fullscreen_ = false;     // in that fullscreen now
    WindowedPlace windowed_;
    void* context_ = nullptr;
    std::unique_ptr<gl::DebugSink> debug_;
};

// True if a real (non-offscreen, non-dummy) video driver could open a window.
bool display_available(std::string* why);
// Starts SDL video (if not yet) and names the driver it chose ("x11", "wayland", "offscreen",
// ...). SDL falls back to an invisible driver when DISPLAY names a display it cannot reach.
// Throws UserError when no driver starts.
std::string start_video();
// True for SDL's drivers that show nothing on any screen.
bool is_invisible_driver(const std::string& driver);

}  // namespace bz::platform
