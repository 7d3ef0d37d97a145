#include "platform/gl_context.h"

#include <SDL.h>

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "gl/driver.h"
#include "gl/gl.h"

namespace bz::platform {

namespace {

void init_video() {
    if (SDL_WasInit(SDL_INIT_VIDEO)) return;
    if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) {
        throw UserError(std::string("cannot start SDL video: ") + SDL_GetError());
    }
}

}  // namespace

GlContext::GlContext(const ContextOptions& o) : debug_(std::make_unique<gl::DebugSink>()) {
    init_video();
    // An extra reference to the GL library, never dropped (SDL counts them): SDL would otherwise
    // unload libEGL and the Mesa driver with the last GL window, and allocations those
    // libraries keep for the process's life would then show up as leaks from an unknown module,
    // which the sanitizer's suppressions (matched by library name) cannot cover.
    SDL_GL_LoadLibrary(nullptr);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 4);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 5);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_FLAGS, o.debug ? SDL_GL_CONTEXT_DEBUG_FLAG : 0);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 0);  // every pass renders into its own targets
    SDL_GL_SetAttribute(SDL_GL_FRAMEBUFFER_SRGB_CAPABLE, 0);
    Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_ALLOW_HIGHDPI;
    if (o.mode == WindowMode::hidden) flags |= SDL_WINDOW_HIDDEN;
    const char* driver = SDL_GetCurrentVideoDriver();
    resize_for_fullscreen_ = driver && std::strcmp(driver, "x11") == 0;
    if (o.mode == WindowMode::fullscreen_desktop && !resize_for_fullscreen_) {
        flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
    }
    if (o.mode != WindowMode::hidden) flags |= SDL_WINDOW_RESIZABLE;
    window_ = SDL_CreateWindow(o.title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                               o.width, o.height, flags);
    if (!window_) throw UserError(std::string("cannot open a window: ") + SDL_GetError());
    context_ = SDL_GL_CreateContext(window_);
    if (!context_) {
        const std::string why = SDL_GetError();
        SDL_DestroyWindow(window_);
        throw UserError("cannot create an OpenGL 4.5 core context: " + why);
    }
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(SDL_GL_GetProcAddress))) {
        SDL_GL_DeleteContext(context_);
        SDL_DestroyWindow(window_);
        throw UserError("cannot load OpenGL 4.5 functions");
    }
    if (o.debug && GLAD_GL_KHR_debug) debug_->install();
    if (o.mode == WindowMode::fullscreen_desktop && resize_for_fullscreen_) set_fullscreen(true);
}

GlContext::~GlContext() {
    if (context_) SDL_GL_DeleteContext(context_);
    if (window_) SDL_DestroyWindow(window_);
}

std::string GlContext::renderer_name() const {
    return gl::renderer_name();
}

std::string start_video() {
    init_video();
    const char* d = SDL_GetCurrentVideoDriver();
    return d ? d : "none";
}

bool is_invisible_driver(const std::string& driver) {
    return driver == "offscreen" || driver == "dummy" || driver == "evdev";
}

bool GlContext::is_software() const {
    return gl::is_software_renderer();
}

void GlContext::drawable_size(int& w, int& h) const {
    SDL_GL_GetDrawableSize(window_, &w, &h);
}

void GlContext::swap() {
    SDL_GL_SwapWindow(window_);
}

Vsync GlContext::set_vsync(Vsync v) {
    if (v == Vsync::adaptive) {
        if (SDL_GL_SetSwapInterval(-1) == 0) return Vsync::adaptive;
        v = Vsync::on;
    }
    if (v == Vsync::on) {
        if (SDL_GL_SetSwapInterval(1) == 0) return Vsync::on;
    }
    SDL_GL_SetSwapInterval(0);
    return Vsync::off;
}

void GlContext::set_fullscreen(bool on) {
    if (on == fullscreen()) return;
    if (!resize_for_fullscreen_) {
        SDL_SetWindowFullscreen(window_, on ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
        return;
    }
    if (on) {
        SDL_Rect bounds;
        if (SDL_GetDisplayBounds(std::max(0, SDL_GetWindowDisplayIndex(window_)), &bounds) != 0) {
            SDL_SetWindowFullscreen(window_, SDL_WINDOW_FULLSCREEN_DESKTOP);  // the usual way
            return;
        }
        SDL_GetWindowPosition(window_, &windowed_.x, &windowed_.y);
        SDL_GetWindowSize(window_, &windowed_.w, &windowed_.h);
        SDL_SetWindowBordered(window_, SDL_FALSE);
        SDL_SetWindowPosition(window_, bounds.x, bounds.y);
        SDL_SetWindowSize(window_, bounds.w, bounds.h);
        SDL_RaiseWindow(window_);
        resized_fullscreen_ = true;
    } else {
        if (SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP) {
            SDL_SetWindowFullscreen(window_, 0);
        }
        if (resized_fullscreen_) {
            SDL_SetWindowSize(window_, windowed_.w, windowed_.h);
            SDL_SetWindowPosition(window_, windowed_.x, windowed_.y);
            SDL_SetWindowBordered(window_, SDL_TRUE);
        }
        resized_fullscreen_ = false;
    }
}

bool GlContext::fullscreen() const {
    return resized_fullscreen_ ||
           (SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
}

bool display_available(std::string* why) {
    const char* driver = SDL_getenv("SDL_VIDEODRIVER");
    if (driver && (std::strcmp(driver, "offscreen") == 0 || std::strcmp(driver, "dummy") == 0)) {
        if (why) *why = std::string("SDL_VIDEODRIVER=") + driver + " cannot show a window";
        return false;
    }
    if (!SDL_getenv("DISPLAY") && !SDL_getenv("WAYLAND_DISPLAY")) {
        if (why) *why = "neither DISPLAY nor WAYLAND_DISPLAY is set";
        return false;
    }
    return true;
}

}  // namespace bz::platform
