#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "core/parallel_chunks.h"
#include "gl/driver.h"
#include "render/clear_image.h"
#include "render/frame_passes.h"
#include "render/lines/edge_prefilter.h"
#include "render/lines/intersection_records.h"
#include "render/styles/palette.h"

namespace bz::render {

namespace {

// The pixel rows below FrameList::view_top (NDC y) that the scene may light, rounded so the
// HUD band's edge is never lit; 0 means all of them.
int scene_view_rows(float view_top, int height) {
    const float top = std::clamp(view_top, -1.0f, 1.0f);
    if (top >= 1.0f) return 0;
    return std::max(1, static_cast<int>((top + 1.0f) * 0.5f * static_cast<float>(height)));
}

}  // namespace

struct Renderer::Impl {
    RenderSettings settings;
    // The settings the passes see: `settings` with LineMethod::automatic resolved for the
    // frame being drawn (resolve_line_method).
    RenderSettings frame_settings;
    int width;
    int height;
    gl::PassTimer timer;
    Programs programs;
    // This frame's images, as many as the lists drawn since the last cut named (ensure_targets).
    Targets targets;
    // What the view keeps from frame to frame, and the rules for forgetting it (frame_history.h).
    FrameHistory history;
    // The style of the last frame drawn (a frame of another style forgets the history).
    std::optional<scene::Style> last_style;
    StyleTextures style_textures = make_style_textures();
    gl::Buffer instances;
    gl::Buffer triangle_draws;  // the prepass's and fills' indirect draws (draw_batch_triangles)
    gl::Buffer raster_work;     // the compute prepass's work items (lines/prepass_raster.h)
    MeshCache gpu_meshes{instances};
    EdgeStorage edges;
    WorkerPool workers{worker_threads()};
    // Intersection lines: the crossings, kept while nothing moves, and the frame's segments
    // in view space for intersections.comp.
    IntersectionCache intersection_cache;
    gl::Buffer intersection_buffer;
    std::uint32_t intersection_count = 0;
    gl::VertexArray empty_vao;
    gl::Buffer hud_vertices;
    gl::VertexArray hud_vao;
    FrameStats stats;
    GLuint last_target = 0;
    // Feature edges per frame, read back as late as the pass times (no mid-frame wait).
    EdgeCounter edge_counter;
    // Whether the last frame filled the edge buffer. A frame the geometry shader drew under
    // LineMethod::automatic leaves it as an older frame filled it: its kept counts are stale.
    bool edges_filled_last_frame = false;
    // Software rasteriser (llvmpipe) or hardware GPU: LineMethod::automatic picks by it.
    const bool software = gl::is_software_renderer();
    // ColourClears::automatic on a GPU: both clear paths timed at this size (clear_image.h),
    // once per size.
    std::optional<ClearTiming> clear_timing;

    Impl(const RenderSettings& s, int w, int h, gl::TimingMethod timing)
        : settings(s),
          frame_settings(s),
          width(std::max(w, 1)),
          height(std::max(h, 1)),
          timer(timing),
          edge_counter(timer.latency()) {
        programs = load_programs(settings);
        remake(HistoryCut::resize);
        hud_vao.bind_buffer(0, hud_vertices, sizeof(float) * 6);
        hud_vao.float_attribute(0, 0, 2, 0);
        hud_vao.float_attribute(1, 0, 3, sizeof(float) * 2);
        hud_vao.float_attribute(2, 0, 1, sizeof(float) * 5);
    }

    // New targets and history for the size and settings: nothing allocated until a frame's
    // list names it (ensure_targets), nothing kept.
    void remake(HistoryCut why) {
        if (why == HistoryCut::resize) clear_timing.reset();
        targets = make_targets(width, height, settings, {});
        history = FrameHistory::make(width, height, 1, 1, {}, why);
    }

    // The targets a list needs, allocated from it: grown (keeping what is there) when it needs
    // more; after a style change, made afresh so that images only the old style used go.
    // The history's images likewise: made (blank) when a list first needs them, and dropped
    // after a style change (which forgot them) to one that does not.
    void ensure_targets(ResourceSet needed, bool style_changed) {
        if (style_changed && !needed.contains(targets.allocated)) {
            targets = make_targets(width, height, settings, needed);
        } else if (!targets.allocated.contains(needed)) {
            targets = grow_targets(std::move(targets), width, height, settings,
                                   targets.allocated | needed);
        }
        if (!history.has_images_for(needed) ||
            (style_changed && history.has_images_beyond(needed))) {
            const glm::ivec2 b = bloom_size(width, height, settings);
            history = FrameHistory::make(width, height, b.x, b.y, needed, history.last_cut());
        }
    }

    const StyleDef& style_of(const scene::FrameList& frame) const {
        return style_def(settings.style ? *settings.style : frame.style);
    }

    bool clears_by_compute() {
        switch (clear_path(settings, software)) {
            case ClearPath::pipeline:
                return false;
            case ClearPath::compute:
                return true;
            case ClearPath::measure:
                break;
        }
        if (!clear_timing) clear_timing = time_colour_clears(programs.clear_image, width, height);
        return clear_timing->compute_is_faster();
    }

    // `dense_downsample`: the drawn frame's choice (dense_first_downsample below); held
    // frames and masks draw no bloom, so they need not read the count it reads.
    PassContext context(const scene::MeshLibrary& meshes, const FrameBatches& batches,
                        const CameraMatrices& cam, const StyleDef& style, GLsizei hud_count,
                        GLuint target, const scene::FrameList& frame, FramePicture* picture,
                        bool dense_downsample = false) {
        const int view_rows = scene_view_rows(frame.view_top, height);
        return PassContext{.programs = programs,
                           .targets = targets,
                           .history = history,
                           .gpu_meshes = gpu_meshes,
                           .meshes = meshes,
                           .batches = batches,
                           .cam = cam,
                           .settings = frame_settings,
                           .occlusion = style.hidden_lines_removed,
                           .empty_vao = empty_vao,
                           .instances = instances,
                           .edges = edges,
                           .workers = workers,
                           .style = style,
                           .style_textures = style_textures,
                           .hud_vao = hud_vao,
                           .hud_vertex_count = hud_count,
                           .target_fbo = target,
                           .stats = &stats,
                           .edge_counter = &edge_counter,
                           .picture = picture,
                           .seed = frame.seed,
                           .view_rows = view_rows,
                           .triangle_draws = &triangle_draws,
                           .raster_work = &raster_work,
                           .software_rasteriser = software,
                           .clears_by_compute = clears_by_compute(),
                           .dense_first_downsample = dense_downsample,
                           .intersections = &intersection_buffer,
                           .intersection_count = intersection_count};
    }

    // RenderSettings::first_downsample's choice for a frame of `style`. Automatic reads how many
    // tiles the frame before listed (Targets::lit_tile_count): where half the screen or more
    // was lit, the beam's tile marks would spare the downsample little, and on llvmpipe their
    // cost in the single-threaded vertex stage and the downsample's quad per tile cost more
    // than the texels (the seed's hallway, 80 % lit: lines and bloom 1.5-2 ms faster dense;
    // the classic level and Suzanne, 16-18 %: bloom 0.5-0.8 ms slower dense;
    // docs/measurements/first-downsample.md). A GPU keeps the marks (not measured).
    bool dense_first_downsample(const StyleDef& style) const {
        if (style.fill != FillPass::none) return false;  // the fill's marks serve the ink HUD
        switch (frame_settings.first_downsample) {
            case FirstDownsample::sparse:
                return false;
            case FirstDownsample::dense:
                return true;
            case FirstDownsample::automatic:
                break;
        }
        if (!software || !targets.lit_tiles || !history.frame_writes().has(Resource::tile_list))
            return false;
        GLuint listed = 0;
        glGetNamedBufferSubData(targets.lit_tile_count.id(), 0, sizeof(listed), &listed);
        const auto tiles =
            static_cast<GLuint>(targets.lit_tiles.width() * targets.lit_tiles.height());
        return 2 * static_cast<std::uint64_t>(listed) >= tiles;
    }

    CameraMatrices camera(const scene::FrameList& frame) const {
        return camera_matrices(frame.camera, static_cast<double>(width) / height, settings.depth);
    }

    FrameBatches prepare(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                         const CameraMatrices& cam) {
        // A style with its own palette recolours the objects (enemies, shells, wrecks ...).
        const scene::Palette& palette = style_of(frame).palette;
        scene::FrameList recoloured;
        if (palette.remap) {
            recoloured.camera = frame.camera;
            recoloured.items = frame.items;
            recoloured.style = frame.style;
            recoloured.view_top = frame.view_top;
            recoloured.cut = frame.cut;
            for (scene::DrawItem& item : recoloured.items)
                item.color = palette_colour(palette, item.color);
        }
        FrameBatches b =
            build_batches(palette.remap ? recoloured : frame, meshes, cam, settings, height);
        instances.set(std::span<const InstanceData>(b.instances), GL_STREAM_DRAW);
        // Far objects may draw a simplified mesh: count what is really submitted.
        b.stats.triangles_submitted = 0;
        for (const Batch& batch : b.batches) {
            b.stats.triangles_submitted +=
                gpu_meshes.get(meshes, batch.mesh, batch.lod).triangle_count() *
                static_cast<std::size_t>(batch.instance_count);
        }
        prepare_intersections(frame, meshes, cam, b);
        return b;
    }

    // Intersection lines: the cache catches up with the frame (computing only what moved or
    // is new), and the segments of the objects drawn go to the GPU in view space.
    void prepare_intersections(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                               const CameraMatrices& cam, FrameBatches& b) {
        intersection_count = 0;
        if (!settings.intersection_lines) return;
        intersection_cache.update(frame.items, meshes);
        const std::vector<IntersectionRecord> records =
            intersection_records(intersection_cache.segments(), b, frame.items, cam.view);
        b.stats.intersections = intersection_cache.stats();
        b.stats.intersection_records = records.size();
        intersection_count = static_cast<std::uint32_t>(records.size());
        if (!records.empty())
            intersection_buffer.set(std::span<const IntersectionRecord>(records), GL_STREAM_DRAW);
    }

    // Picks the frame's line method (LineMethod::automatic: by the triangles it submits) and
    // keeps the edge buffer's per-frame state true to it: a frame that fills the buffer after
    // one that did not must size it from its own counts, not from the last frame that filled it
    // (which may be many frames and a much smaller scene ago). `fills_edges` says whether the
    // frame's passes fill the edge buffer (frame_passes.h).
    void choose_line_method(const FrameBatches& batches, const StyleDef& style,
                            bool (*fills_edges)(const StyleDef&, const RenderSettings&)) {
        frame_settings.method =
            resolve_line_method(settings.method, batches.stats.triangles_submitted, software,
                                settings.auto_compute_from_triangles);
        const bool fills = fills_edges(style, frame_settings);
        if (fills && !edges_filled_last_frame) edges.forget_previous();
        edges_filled_last_frame = fills;
    }

    // The history rules that a frame itself triggers (frame_history.h): keep_history off,
    // a cut, a style other than the last frame's. Returns whether the style changed.
    bool apply_history_rules(const scene::FrameList& frame, const StyleDef& style) {
        const bool style_changed = last_style && *last_style != style.id;
        if (!settings.keep_history) {
            history.forget(HistoryCut::no_history);
        } else if (frame.cut) {
            history.forget(HistoryCut::camera_cut);
        } else if (style_changed) {
            history.forget(HistoryCut::style_change);
        }
        last_style = style.id;
        return style_changed;
    }

    // Runs a list in order, each pass timed under its name and told what the passes before it
    // wrote; `frame` starts with what the list may read of an earlier frame.
    void run_passes(const std::vector<FramePass>& list, PassContext ctx, FrameResources frame) {
        ctx.frame = &frame;
        timer.begin_frame();
        edge_counter.begin_frame();
        for (const FramePass& pass : list) {
            timer.begin(pass.name);
            pass.run(ctx);
            timer.end();
            frame.written.add(pass.writes);
        }
        timer.end_frame();
        stats.feature_edges = edge_counter.end_frame();
    }

    GLsizei upload_hud(const std::vector<scene::HudLine>& hud) {
        std::vector<float> v;
        v.reserve(hud.size() * 12);
        for (const auto& l : hud) {
            const glm::vec3 c = l.color * l.intensity;
            for (const glm::vec2& p : {l.a, l.b})
                v.insert(v.end(), {p.x, p.y, c.r, c.g, c.b, l.intensity});
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
    impl_->remake(HistoryCut::resize);
}

void Renderer::set_settings(const RenderSettings& settings) {
    const BeamSettings& old_beam = impl_->settings.beam;
    const bool remake =
        settings.depth != impl_->settings.depth ||
        settings.bloom_resolution != impl_->settings.bloom_resolution ||
        settings.method != impl_->settings.method || settings.beam.bloom != old_beam.bloom ||
        // The compute prepass's image is there unless the pipeline draws every triangle.
        (settings.prepass_raster == PrepassRaster::pipeline) !=
            (impl_->settings.prepass_raster == PrepassRaster::pipeline) ||
        settings.beam.mip_weights.size() != old_beam.mip_weights.size() ||
        (settings.beam.phosphor == PhosphorDecay::off) != (old_beam.phosphor == PhosphorDecay::off);
    const bool new_kernel = settings.bloom_taps != impl_->settings.bloom_taps ||
                            settings.bloom_sigma_px != impl_->settings.bloom_sigma_px;
    if (new_kernel) {
        impl_->programs.bloom_blur = load_bloom_blur(settings, false);
        impl_->programs.bloom_blur_glow = load_bloom_blur(settings, true);
    }
    impl_->settings = settings;
    impl_->frame_settings = settings;
    if (remake) impl_->remake(HistoryCut::settings_change);
}

const RenderSettings& Renderer::settings() const {
    return impl_->settings;
}
LineMethod Renderer::line_method_drawn() const {
    return impl_->frame_settings.method;
}

namespace {

// With a held refresh (BeamSettings::refresh_hz), frames whose times fall into the same
// refresh period show the same picture.
bool same_refresh(double hz, double a_s, double b_s) {
    return hz > 0.0 && std::floor(a_s * hz) == std::floor(b_s * hz);
}

}  // namespace

void Renderer::render(const scene::FrameList& frame, const scene::MeshLibrary& meshes,
                      unsigned target_fbo) {
    Impl& m = *impl_;
    const StyleDef& style = m.style_of(frame);
    const bool style_changed = m.apply_history_rules(frame, style);
    const ResourceSet output =
        target_fbo == kOffscreen ? ResourceSet{Resource::target} : ResourceSet{};
    const CameraMatrices cam = m.camera(frame);
    if (m.history.picture() &&
        same_refresh(m.settings.beam.refresh_hz, frame.time_s, m.history.time_s())) {
        // The original machine redrew at ~41 Hz: hold the last picture, only show it again.
        // The held list reads what the frame it holds wrote; the history stays as it is.
        const std::vector<FramePass> held = frame_passes(style, m.frame_settings, FrameKind::held);
        m.ensure_targets(resources_of(held) | output, false);
        const GLuint target = target_fbo == kOffscreen ? m.targets.output_fbo.id() : target_fbo;
        m.last_target = target;
        const FrameBatches none;
        const PassContext ctx = m.context(meshes, none, cam, style, 0, target, frame, nullptr);
        // a held frame draws no edges itself: feature_edges reads back an earlier frame's
        m.run_passes(held, ctx, FrameResources{m.history.frame_writes()});
        return;
    }
    m.gpu_meshes.set_edge_lists(style_needs_edge_buffer(style, m.settings));
    m.gpu_meshes.set_edge_facing_tables(uses_edge_prefilter(m.settings, m.software));
    const FrameBatches batches = m.prepare(frame, meshes, cam);
    m.choose_line_method(batches, style, style_needs_edge_buffer);
    const std::vector<FramePass> list = frame_passes(style, m.frame_settings);
    m.ensure_targets(resources_of(list) | output, style_changed);
    const GLsizei hud_count = m.upload_hud(frame.hud);
    m.stats = batches.stats;
    m.stats.line_method = m.frame_settings.method;
    const GLuint target = target_fbo == kOffscreen ? m.targets.output_fbo.id() : target_fbo;
    m.last_target = target;
    // A picture without a past (the history holds none: new targets, a cut, a frame with no
    // beam picture): the phosphor and the glow start from black, so nothing an earlier frame
    // lit can linger in it.
    if (!m.history.picture()) m.history.forget(HistoryCut::no_past);
    const gl::Texture2D* past = m.history.picture();
    FramePicture picture{
        &m.targets.lines, past ? frame.time_s - m.history.time_s() : 0.0, false, {}};
    const PassContext ctx = m.context(meshes, batches, cam, style, hud_count, target, frame,
                                      &picture, m.dense_first_downsample(style));
    // The frame is the style's list of passes (frame_passes.cpp), each timed under its name.
    m.run_passes(list, ctx, FrameResources{});
    // The history now holds what this frame wrote of it: only a beam style writes a picture
    // that a held frame can show again (pass_composite).
    m.history.keep(writes_of(list), picture.texture, frame.time_s);
}

std::vector<std::uint8_t> Renderer::render_mask(const scene::FrameList& frame,
                                                const scene::MeshLibrary& meshes) {
    Impl& m = *impl_;
    const CameraMatrices cam = m.camera(frame);
    const StyleDef& style = m.style_of(frame);
    m.gpu_meshes.set_edge_lists(mask_needs_edge_buffer(style, m.settings));
    m.gpu_meshes.set_edge_facing_tables(uses_edge_prefilter(m.settings, m.software));
    const FrameBatches batches = m.prepare(frame, meshes, cam);
    m.choose_line_method(batches, style, mask_needs_edge_buffer);
    const std::vector<FramePass> list = mask_passes(style, m.frame_settings);
    m.ensure_targets(resources_of(list), false);
    const PassContext ctx =
        m.context(meshes, batches, cam, style, 0, m.targets.output_fbo.id(), frame, nullptr);
    for (const FramePass& pass : list) pass.run(ctx);
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
    // The level mask keeps its codes (RenderSettings::mask_occlusion_levels).
    if (!m.frame_settings.mask_occlusion_levels)
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
    return read_hdr(impl_->targets.lines);
}

std::vector<float> Renderer::read_picture_hdr() {
    const gl::Texture2D* picture = impl_->history.picture();
    return read_hdr(picture ? *picture : impl_->targets.lines);
}

std::vector<EdgeRecord> Renderer::read_edge_records() {
    const EdgeStorage& edges = impl_->edges;
    if (edges.capacity() == 0) return {};
    const std::size_t n =
        std::min<std::size_t>(edges.counts().records, static_cast<std::size_t>(edges.capacity()));
    std::vector<EdgeRecord> records(n);
    if (n == 0) return records;
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(edges.records().id(), 0,
                            static_cast<GLsizeiptr>(n * sizeof(EdgeRecord)), records.data());
    return records;
}

std::vector<glm::ivec2> Renderer::read_lit_tiles() {
    const Targets& t = impl_->targets;
    // Only when the last frame drawn built it (FrameHistory::frame_writes).
    if (!impl_->history.frame_writes().has(Resource::tile_list) || !t.lit_tiles) return {};
    const std::size_t capacity =
        static_cast<std::size_t>(t.lit_tiles.width()) * t.lit_tiles.height();
    std::vector<GLuint> words(4 + capacity);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(t.tile_list.id(), 0,
                            static_cast<GLsizeiptr>(words.size() * sizeof(GLuint)), words.data());
    const std::size_t count = std::min<std::size_t>(words[1], capacity);  // the instance count
    std::vector<glm::ivec2> tiles;
    for (std::size_t i = 0; i < count; ++i) {
        // A run along a row, packed as shaders/beam/lit_tiles.glsl's encode_tile_run.
        const GLuint code = words[4 + i];
        const int x = static_cast<int>(code & 0xfffu), y = static_cast<int>((code >> 12) & 0xfffu);
        const int length = static_cast<int>(code >> 24) + 1;
        for (int k = 0; k < length; ++k) tiles.emplace_back(x + k, y);
    }
    std::sort(tiles.begin(), tiles.end(),
              [](glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    return tiles;
}

std::vector<std::uint8_t> Renderer::read_bloom(glm::ivec2* size) {
    const gl::Texture2D& bloom = impl_->targets.bloom_out;
    *size = glm::ivec2(bloom.width(), bloom.height());
    std::vector<std::uint8_t> out(static_cast<std::size_t>(size->x) * size->y * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(bloom.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(out.size()),
                      out.data());
    return out;
}

std::vector<float> Renderer::read_depth() {
    Impl& m = *impl_;
    std::vector<float> out(static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height));
    if (!m.targets.depth) return out;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(m.targets.depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
    return out;
}

std::vector<float> Renderer::read_hdr(const gl::Texture2D& texture) {
    Impl& m = *impl_;
    const std::size_t row = static_cast<std::size_t>(m.width) * 4;
    std::vector<float> rows(row * static_cast<std::size_t>(m.height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(rows.size() * sizeof(float)), rows.data());
    std::vector<float> out(rows.size());
    for (int y = 0; y < m.height; ++y) {
        std::copy_n(
            rows.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row), row,
            out.begin() +
                static_cast<std::ptrdiff_t>(static_cast<std::size_t>(m.height - 1 - y) * row));
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

const std::vector<gl::PassTime>& Renderer::pass_times() const {
    return impl_->timer.last_results();
}
int Renderer::pass_times_latency() const {
    return impl_->timer.latency();
}
gl::TimingMethod Renderer::timing_method() const {
    return impl_->timer.method();
}
std::size_t Renderer::gpu_mesh_uploads() const {
    return impl_->gpu_meshes.uploads();
}
ResourceSet Renderer::allocated_resources() const {
    return impl_->targets.allocated;
}
std::size_t Renderer::allocated_bytes() const {
    const FrameHistory& h = impl_->history;
    return render::allocated_bytes(impl_->targets) + texture_bytes(h.phosphor) +
           texture_bytes(h.picture_lit) + texture_bytes(h.glow);
}
ResourceSet Renderer::history_held() const {
    return impl_->history.held();
}
HistoryCut Renderer::history_last_cut() const {
    return impl_->history.last_cut();
}
bool Renderer::colour_clears_by_compute() {
    return impl_->clears_by_compute();
}
std::optional<ClearTiming> Renderer::colour_clear_timing() const {
    return impl_->clear_timing;
}
const FrameStats& Renderer::stats() const {
    return impl_->stats;
}
std::size_t Renderer::hiz_hidden_clusters() const {
    return impl_->edges.counts().hidden_items;
}
int Renderer::width() const {
    return impl_->width;
}
int Renderer::height() const {
    return impl_->height;
}

}  // namespace bz::render
