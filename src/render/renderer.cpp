#include "render/renderer.h"

#include <algorithm>

#include "core/error.h"
#include "render/frame_passes.h"

namespace bz::render {

struct Renderer::Impl {
    RenderSettings settings;
    int width;
    int height;
    gl::PassTimer timer;
    Programs programs;
    Targets targets;
    StyleTextures style_textures = make_style_textures();
    gl::Buffer instances;
    MeshCache gpu_meshes{instances};
    EdgeStorage edges;
    gl::VertexArray empty_vao;
    gl::Buffer hud_vertices;
    gl::VertexArray hud_vao;
    FrameStats stats;
    GLuint last_target = 0;
    GLuint edge_query = 0;

    Impl(const RenderSettings& s, int w, int h, gl::TimingMethod timing)
        : settings(s), width(std::max(w, 1)), height(std::max(h, 1)), timer(timing) {
        programs = load_programs(settings);
        targets = make_targets(width, height, settings);
        hud_vao.bind_buffer(0, hud_vertices, sizeof(float) * 5);
        hud_vao.float_attribute(0, 0, 2, 0);
        hud_vao.float_attribute(1, 0, 3, sizeof(float) * 2);
        glGenQueries(1, &edge_query);
    }
    ~Impl() { glDeleteQueries(1, &edge_query); }

    const StyleDef& style_of(const scene::FrameList& frame) const {
        return style_def(settings.style ? *settings.style : frame.style);
    }

    PassContext context(const scene::MeshLibrary& meshes, const FrameBatches& batches,
                        const CameraMatrices& cam, const StyleDef& style, GLsizei hud_count,
                        GLuint target) {
        return PassContext{programs,  targets,  gpu_meshes, meshes,
                           batches,   cam,      settings,   style.hidden_lines_removed,
                           empty_vao, instances, edges,     style,
                           style_textures, hud_vao, hud_count, target,
                           &stats,    edge_query};
    }

    CameraMatrices camera(const scene::FrameList& frame) const {
        return camera_matrices(frame.camera, static_cast<double>(width) / height, settings.depth);
    }

    FrameBatches prepare(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                         const CameraMatrices& cam) {
        FrameBatches b = build_batches(frame, meshes, cam, settings, height);
        instances.set(std::span<const InstanceData>(b.instances), GL_STREAM_DRAW);
        // Far objects may draw a simplified mesh: count what is really submitted.
        b.stats.triangles_submitted = 0;
        for (const Batch& batch : b.batches) {
            b.stats.triangles_submitted += gpu_meshes.get(meshes, batch.mesh, batch.lod).triangle_count() *
                                           static_cast<std::size_t>(batch.instance_count);
        }
        return b;
    }

    GLsizei upload_hud(const std::vector<scene::HudLine>& hud) {
        std::vector<float> v;
        v.reserve(hud.size() * 10);
        for (const auto& l : hud) {
            const glm::vec3 c = l.color * l.intensity;
            for (const glm::vec2& p : {l.a, l.b}) v.insert(v.end(), {p.x, p.y, c.r, c.g, c.b});
        }
        hud_vertices.set(std::span<const float>(v), GL_STREAM_DRAW);
        return static_cast<GLsizei>(hud.size() * 2);
    }
};

Renderer::Renderer(const RenderSettings& settings, int width, int height, gl::TimingMethod timing)
    : impl_(std::make_unique<Impl>(settings, width, height, timing)) {}

Renderer::~Renderer() = default;

void Renderer::resize(int width, int height) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    if (width == impl_->width && height == impl_->height) return;
    impl_->width = width;
    impl_->height = height;
    impl_->targets = make_targets(width, height, impl_->settings);
}

void Renderer::set_settings(const RenderSettings& settings) {
    const bool remake = settings.depth != impl_->settings.depth ||
                        settings.bloom_resolution != impl_->settings.bloom_resolution ||
                        settings.method != impl_->settings.method;
    const bool new_kernel = settings.bloom_taps != impl_->settings.bloom_taps ||
                            settings.bloom_sigma_px != impl_->settings.bloom_sigma_px;
    if (new_kernel) impl_->programs.bloom_blur = load_bloom_blur(settings);
    impl_->settings = settings;
    if (remake) impl_->targets = make_targets(impl_->width, impl_->height, settings);
}

const RenderSettings& Renderer::settings() const { return impl_->settings; }

void Renderer::render(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                      unsigned target_fbo) {
    Impl& m = *impl_;
    const CameraMatrices cam = m.camera(frame);
    const StyleDef& style = m.style_of(frame);
    m.gpu_meshes.set_edge_lists(style_needs_edge_buffer(style));
    const FrameBatches batches = m.prepare(frame, meshes, cam);
    const GLsizei hud_count = m.upload_hud(frame.hud);
    m.stats = batches.stats;
    const GLuint target = target_fbo == kOffscreen ? m.targets.output_fbo.id() : target_fbo;
    m.last_target = target;
    const PassContext ctx = m.context(meshes, batches, cam, style, hud_count, target);

    // The frame is the style's list of passes (frame_passes.cpp), each timed under its name.
    m.timer.begin_frame();
    for (const FramePass& pass : frame_passes(style, m.settings)) {
        m.timer.begin(pass.name);
        pass.run(ctx);
        m.timer.end();
    }
    m.timer.end_frame();
}

std::vector<std::uint8_t> Renderer::render_mask(const scene::FrameList& frame,
                                                const scene::MeshLibrary& meshes) {
    Impl& m = *impl_;
    const CameraMatrices cam = m.camera(frame);
    const StyleDef& style = m.style_of(frame);
    m.gpu_meshes.set_edge_lists(style_needs_edge_buffer(style));
    const FrameBatches batches = m.prepare(frame, meshes, cam);
    const PassContext ctx = m.context(meshes, batches, cam, style, 0, m.targets.output_fbo.id());
    for (const FramePass& pass : mask_passes(style, m.settings)) pass.run(ctx);
    std::vector<std::uint8_t> rows(static_cast<std::size_t>(m.width) * m.height);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(m.targets.mask.id(), 0, GL_RED, GL_UNSIGNED_BYTE,
                      static_cast<GLsizei>(rows.size()), rows.data());
    // GL's row 0 is the bottom; images put the top first.
    std::vector<std::uint8_t> out(rows.size());
    for (int y = 0; y < m.height; ++y) {
        std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(y) * m.width, m.width,
                    out.begin() + static_cast<std::ptrdiff_t>(m.height - 1 - y) * m.width);
    }
    for (auto& v : out) v = v ? 255 : 0;
    return out;
}

std::vector<std::uint8_t> Renderer::read_color() {
    Impl& m = *impl_;
    const std::size_t row = static_cast<std::size_t>(m.width) * 4;
    std::vector<std::uint8_t> rows(row * m.height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, m.last_target);
    if (m.last_target == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, m.width, m.height, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
    std::vector<std::uint8_t> out(rows.size());
    for (int y = 0; y < m.height; ++y) {
        std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(y * row), row,
                    out.begin() + static_cast<std::ptrdiff_t>((m.height - 1 - y) * row));
    }
    return out;
}

std::vector<float> Renderer::read_lines_hdr() {
    Impl& m = *impl_;
    const std::size_t row = static_cast<std::size_t>(m.width) * 4;
    std::vector<float> rows(row * static_cast<std::size_t>(m.height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(m.targets.lines.id(), 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(rows.size() * sizeof(float)), rows.data());
    std::vector<float> out(rows.size());
    for (int y = 0; y < m.height; ++y) {
        std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row), row,
                    out.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(m.height - 1 - y) * row));
    }
    return out;
}

bool Renderer::reload_shaders(std::string* error) {
    try {
        impl_->programs = load_programs(impl_->settings);
        return true;
    } catch (const UserError& e) {
        if (error) *error = e.what();
        return false;
    }
}

const std::vector<gl::PassTime>& Renderer::pass_times() const { return impl_->timer.last_results(); }
int Renderer::pass_times_latency() const { return impl_->timer.latency(); }
gl::TimingMethod Renderer::timing_method() const { return impl_->timer.method(); }
std::size_t Renderer::gpu_mesh_uploads() const { return impl_->gpu_meshes.uploads(); }
const FrameStats& Renderer::stats() const { return impl_->stats; }
int Renderer::width() const { return impl_->width; }
int Renderer::height() const { return impl_->height; }

}  // namespace bz::render
