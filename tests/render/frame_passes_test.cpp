// The frame's pass lists as data (render/frame_passes.h), on the CPU alone: for every style x
// line method x beam look, the passes and their order, and that every image a pass reads was
// written by an earlier pass of the same list, or is declared as read from an earlier frame
// that the same style's drawn frame writes. No GL: frame_passes() only builds the list.
#include "render/frame_passes.h"

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>

#include "render/styles/style_def.h"

namespace {

using bz::render::FrameKind;
using bz::render::FramePass;
using bz::render::LineMethod;
using bz::render::RenderSettings;
using bz::render::Resource;
using bz::render::ResourceSet;
using bz::scene::Style;

// The line methods a list is built for: the resolved ones (LineMethod::automatic draws each
// frame with one of the first two).
constexpr LineMethod kMethods[] = {LineMethod::compute, LineMethod::geometry_shader,
                                   LineMethod::image_outline};

std::string names(const std::vector<FramePass>& list) {
    std::string out;
    for (const FramePass& pass : list) out += (out.empty() ? "" : " ") + std::string(pass.name);
    return out;
}

std::string resources(ResourceSet set) {
    std::string out;
    for (int i = 0; i < bz::render::kResourceCount; ++i) {
        const auto r = static_cast<Resource>(i);
        if (set.has(r)) out += (out.empty() ? "" : ",") + std::string(bz::render::resource_name(r));
    }
    return out;
}

// Each read of the list is written before it; each read of an earlier frame is a resource
// that `drawn` (the style's drawn frame) writes, so a frame before this one wrote it. Returns
// the violations, one a line.
std::string check_order(const std::vector<FramePass>& list, ResourceSet drawn) {
    std::ostringstream errors;
    ResourceSet written;
    for (const FramePass& pass : list) {
        for (int i = 0; i < bz::render::kResourceCount; ++i) {
            const auto r = static_cast<Resource>(i);
            if (pass.reads.has(r) && !written.has(r))
                errors << pass.name << " reads " << bz::render::resource_name(r)
                       << " before any pass wrote it\n";
            if (pass.reads_past.has(r) && !drawn.has(r))
                errors << pass.name << " reads " << bz::render::resource_name(r)
                       << " of an earlier frame, which no drawn frame writes\n";
        }
        if (pass.writes.empty()) errors << pass.name << " writes nothing\n";
        written.add(pass.writes);
    }
    return errors.str();
}

struct Row {
    Style style;
    LineMethod method;
    const char* frame;  // the drawn frame's passes (beam looks with bloom and sparse composite)
    const char* mask;   // mask_passes
};

constexpr const char* kBeamCompute = "prepass edges visibility lines bloom hud tiles composite";
constexpr const char* kBeamGs = "prepass lines bloom hud tiles composite";
constexpr const char* kBeamOutline = "prepass outline bloom hud tiles composite";
// vector-xray peels the occlusion layers its lines are dimmed by.
constexpr const char* kXrayCompute =
    "prepass layers edges visibility lines bloom hud tiles composite";
constexpr const char* kXrayGs = "prepass layers lines bloom hud tiles composite";
// technical peels them for its hidden lines.
constexpr const char* kTechnical = "fill edges layers outline hud composite";
constexpr const char* kMaskEdges = "prepass edges visibility lines";
constexpr const char* kMaskLines = "prepass lines";
constexpr const char* kMaskOutline = "prepass outline";
constexpr const char* kMaskSketch = "prepass edges strokes";

const Row kTable[] = {
    {Style::vector, LineMethod::compute, kBeamCompute, kMaskEdges},
    {Style::vector, LineMethod::geometry_shader, kBeamGs, kMaskLines},
    {Style::vector, LineMethod::image_outline, kBeamOutline, kMaskOutline},
    {Style::vector_xray, LineMethod::compute, kXrayCompute, kMaskEdges},
    {Style::vector_xray, LineMethod::geometry_shader, kXrayGs, kMaskLines},
    {Style::vector_xray, LineMethod::image_outline, kBeamOutline, kMaskOutline},
    {Style::toon, LineMethod::compute, "fill edges outline hud composite", kMaskEdges},
    {Style::toon, LineMethod::geometry_shader, "fill edges outline hud composite", kMaskLines},
    {Style::toon, LineMethod::image_outline, "fill edges outline hud composite", kMaskLines},
    {Style::sketch, LineMethod::compute, "fill edges strokes hud composite", kMaskSketch},
    {Style::sketch, LineMethod::geometry_shader, "fill edges strokes hud composite", kMaskSketch},
    {Style::sketch, LineMethod::image_outline, "fill edges strokes hud composite", kMaskSketch},
    {Style::pop_art, LineMethod::compute, "fill edges outline hud composite", kMaskEdges},
    {Style::pop_art, LineMethod::geometry_shader, "fill edges outline hud composite", kMaskLines},
    {Style::pop_art, LineMethod::image_outline, "fill edges outline hud composite", kMaskLines},
    {Style::halo, LineMethod::compute, "fill edges shrunk halo hud composite", kMaskEdges},
    {Style::halo, LineMethod::geometry_shader, "fill edges shrunk halo hud composite", kMaskLines},
    {Style::halo, LineMethod::image_outline, "fill edges shrunk halo hud composite", kMaskLines},
    {Style::technical, LineMethod::compute, kTechnical, kMaskEdges},
    {Style::technical, LineMethod::geometry_shader, kTechnical, kMaskLines},
    {Style::technical, LineMethod::image_outline, kTechnical, kMaskLines},
};

std::string label(const Row& row, const std::string& beam) {
    return std::string(bz::scene::style_name(row.style)) + " / " +
           bz::render::line_method_name(row.method) + " / " + beam;
}

RenderSettings settings_for(LineMethod method, const std::string& beam) {
    RenderSettings s = bz::render::preset("balanced");
    s.method = method;
    s.beam = bz::render::beam_look(beam);
    return s;
}

TEST(FramePassesTest, TheTableCoversEveryStyleAndMethod) {
    std::map<std::pair<Style, LineMethod>, int> rows;
    for (const Row& row : kTable) ++rows[{row.style, row.method}];
    for (Style style : bz::scene::all_styles())
        for (LineMethod method : kMethods)
            EXPECT_EQ((rows[{style, method}]), 1)
                << bz::scene::style_name(style) << " / " << bz::render::line_method_name(method);
}

TEST(FramePassesTest, EveryListHasItsPassesInOrderAndEveryReadAWriter) {
    ASSERT_FALSE(bz::render::beam_look_names().empty());
    for (const Row& row : kTable) {
        const auto& style = bz::render::style_def(row.style);
        for (const std::string& beam : bz::render::beam_look_names()) {
            const RenderSettings s = settings_for(row.method, beam);
            const auto drawn = bz::render::frame_passes(style, s);
            const auto mask = bz::render::mask_passes(style, s);
            const ResourceSet drawn_writes = bz::render::writes_of(drawn);
            SCOPED_TRACE(label(row, beam));
            EXPECT_EQ(names(drawn), row.frame);
            EXPECT_EQ(names(mask), row.mask);
            EXPECT_EQ(check_order(drawn, drawn_writes), "");
            // The mask passes keep nothing from a frame: every read is this list's.
            EXPECT_EQ(check_order(mask, {}), "");
            EXPECT_TRUE(drawn_writes.has(Resource::target)) << "the frame reaches its target";
            EXPECT_TRUE(bz::render::writes_of(mask).has(Resource::mask));
            EXPECT_FALSE(bz::render::resources_of(mask).has(Resource::target));
        }
    }
}

TEST(FramePassesTest, AHeldFrameShowsWhatItsDrawnFrameWrote) {
    for (const Row& row : kTable) {
        const auto& style = bz::render::style_def(row.style);
        for (const std::string& beam : bz::render::beam_look_names()) {
            const RenderSettings s = settings_for(row.method, beam);
            SCOPED_TRACE(label(row, beam));
            const auto drawn = bz::render::frame_passes(style, s);
            const auto held = bz::render::frame_passes(style, s, FrameKind::held);
            const ResourceSet writes = bz::render::writes_of(drawn);
            if (style.fill != bz::render::FillPass::none) {
                // A filled style writes no picture a held frame could show: it is never held.
                EXPECT_FALSE(writes.has(Resource::picture));
                EXPECT_EQ(names(held), names(drawn));
                continue;
            }
            EXPECT_EQ(names(held), "composite");
            EXPECT_EQ(check_order(held, writes), "");
            EXPECT_TRUE(held.front().reads_past.has(Resource::picture));
            EXPECT_TRUE(held.front().reads_past.has(Resource::bloom_out));
            EXPECT_EQ(held.front().writes, ResourceSet{Resource::target});
            // The held list needs no image its drawn frame did not allocate.
            EXPECT_TRUE(bz::render::resources_of(drawn).contains(bz::render::resources_of(held)));
        }
    }
}

// What a list allocates: vector no filled-style image, a filled style no beam image.
TEST(FramePassesTest, ListsNameOnlyTheImagesTheirStyleUses) {
    const ResourceSet beam_only{Resource::bloom_chain, Resource::bloom_out, Resource::lit_tiles,
                                Resource::tile_list,   Resource::phosphor,  Resource::picture_lit,
                                Resource::glow,        Resource::picture};
    for (const Row& row : kTable) {
        const auto& style = bz::render::style_def(row.style);
        for (const std::string& beam : bz::render::beam_look_names()) {
            SCOPED_TRACE(label(row, beam));
            const RenderSettings s = settings_for(row.method, beam);
            const ResourceSet all = bz::render::resources_of(bz::render::frame_passes(style, s));
            if (style.fill == bz::render::FillPass::none) {
                EXPECT_FALSE(all.has(Resource::canvas)) << resources(all);
                EXPECT_FALSE(all.has(Resource::shrunk_depth)) << resources(all);
                EXPECT_FALSE(all.has(Resource::halo)) << resources(all);
                EXPECT_EQ(all.has(Resource::normals), row.method == LineMethod::image_outline);
                // The phosphor's history only where the look has a phosphor.
                const bool phosphor = s.beam.phosphor != bz::render::PhosphorDecay::off;
                EXPECT_EQ(all.has(Resource::phosphor), phosphor) << resources(all);
                EXPECT_EQ(all.has(Resource::glow), phosphor) << resources(all);
            } else {
                for (int i = 0; i < bz::render::kResourceCount; ++i) {
                    const auto r = static_cast<Resource>(i);
                    if (beam_only.has(r)) {
                        EXPECT_FALSE(all.has(r)) << bz::render::resource_name(r);
                    }
                }
                EXPECT_EQ(all.has(Resource::halo), style.lines == bz::render::LinePass::halo);
                EXPECT_EQ(all.has(Resource::shrunk_depth),
                          style.lines == bz::render::LinePass::halo);
                // The HUD marks its tiles for the ink composite.
                EXPECT_TRUE(all.has(Resource::beam_tiles));
            }
        }
    }
}

// The options that change a beam list's tail: no bloom, no sparse composite, no phosphor.
TEST(FramePassesTest, TheBeamTailFollowsBloomSparseCompositeAndPhosphor) {
    const auto& vector = bz::render::style_def(Style::vector);
    for (LineMethod method : kMethods) {
        for (const std::string& beam : bz::render::beam_look_names()) {
            RenderSettings s = settings_for(method, beam);
            SCOPED_TRACE(std::string(bz::render::line_method_name(method)) + " / " + beam);
            // A glowing HUD (tests that draw beam lines as HUD lines) goes before the bloom.
            s.hud_glow = true;
            auto list = bz::render::frame_passes(vector, s);
            EXPECT_LT(names(list).find("hud"), names(list).find("bloom")) << names(list);
            EXPECT_EQ(check_order(list, bz::render::writes_of(list)), "");
            s.hud_glow = false;
            s.sparse_composite = false;
            list = bz::render::frame_passes(vector, s);
            EXPECT_EQ(names(list).find("tiles"), std::string::npos) << names(list);
            EXPECT_EQ(check_order(list, bz::render::writes_of(list)), "");
            EXPECT_FALSE(bz::render::resources_of(list).has(Resource::tile_list));
            s.bloom_strength = 0.0f;
            list = bz::render::frame_passes(vector, s);
            EXPECT_EQ(names(list).find("bloom"), std::string::npos) << names(list);
            EXPECT_EQ(check_order(list, bz::render::writes_of(list)), "");
            EXPECT_FALSE(bz::render::resources_of(list).has(Resource::bloom_chain));
            EXPECT_FALSE(bz::render::writes_of(list).has(Resource::glow))
                << "a frame without bloom leaves no glow to keep";
            const auto held = bz::render::frame_passes(vector, s, FrameKind::held);
            EXPECT_FALSE(bz::render::resources_of(held).has(Resource::bloom_out));
            s.beam.phosphor = bz::render::PhosphorDecay::off;
            list = bz::render::frame_passes(vector, s);
            for (const FramePass& pass : list) EXPECT_TRUE(pass.reads_past.empty()) << pass.name;
        }
    }
}

// The bloom reads the beam's tile marks only in a list whose line pass wrote them: the
// image-space outline marks none, so its bloom reads every pixel.
TEST(FramePassesTest, OnlyALinePassThatMarksTilesFeedsTheSparseDownsample) {
    const auto& vector = bz::render::style_def(Style::vector);
    for (LineMethod method : kMethods) {
        const auto list = bz::render::frame_passes(vector, settings_for(method, "classic"));
        for (const FramePass& pass : list) {
            if (std::string(pass.name) != "bloom") continue;
            EXPECT_EQ(pass.reads.has(Resource::beam_tiles), method != LineMethod::image_outline)
                << bz::render::line_method_name(method);
        }
    }
}

}  // namespace

// Hierarchical-Z culling (RenderSettings::hiz_culling) adds its depth tiles between the
// prepass and the edges pass of the compute list, and only there.
TEST(FramePassesTest, HierarchicalZPutsItsTilesBetweenPrepassAndEdges) {
    const auto& vector = bz::render::style_def(Style::vector);
    for (LineMethod method : kMethods) {
        RenderSettings s = settings_for(method, "classic");
        s.hiz_culling = true;
        const auto list = bz::render::frame_passes(vector, s);
        SCOPED_TRACE(bz::render::line_method_name(method));
        EXPECT_EQ(check_order(list, bz::render::writes_of(list)), "");
        if (method == LineMethod::compute) {
            EXPECT_EQ(names(list), "prepass hiz edges visibility lines bloom hud tiles composite");
        } else {
            EXPECT_EQ(names(list).find("hiz"), std::string::npos) << names(list);
            EXPECT_FALSE(bz::render::resources_of(list).has(Resource::depth_tiles));
        }
    }
}
