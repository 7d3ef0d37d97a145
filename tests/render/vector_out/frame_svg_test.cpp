// The SVG of a frame (no GL): hidden lines grouped by occlusion level in the technical style,
// the beam styles in each object's colour, and the counts the log reports.
#include "render/vector_out/frame_svg.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <regex>
#include <string>

#include "geometry/generated/primitives.h"
#include "geometry/line_mesh/line_mesh.h"

namespace {

using bz::scene::Style;

// The paths in group `id`, or -1 if there is no such group.
int paths_in(const std::string& doc, const std::string& id) {
    const auto start = doc.find("<g id=\"" + id + "\"");
    if (start == std::string::npos) return -1;
    const auto end = doc.find("</g>", start);
    int n = 0;
    for (auto p = doc.find("<path ", start); p < end; p = doc.find("<path ", p + 1)) ++n;
    return n;
}

// A bar behind a cube behind a smaller cube, seen head on (as the reference's own test).
struct ThreeCubes {
    bz::scene::MeshLibrary meshes;
    bz::scene::FrameList frame;
    ThreeCubes(Style style) {
        const auto bar = meshes.add("bar", bz::geo::build_line_mesh(bz::geo::box({3.0, 0.5, 1.0})));
        const auto big = meshes.add("big", bz::geo::build_line_mesh(bz::geo::box({1.0, 1.0, 1.0})));
        const auto small =
            meshes.add("small", bz::geo::build_line_mesh(bz::geo::box({0.3, 0.3, 0.3})));
        auto at = [](double z) { return glm::translate(glm::dmat4(1.0), {0.0, 0.0, z}); };
        frame.items.push_back({bar, at(-4.0), glm::vec3(0.2f, 1.0f, 0.3f), 1.0f, true});
        frame.items.push_back({big, at(0.0), glm::vec3(1.0f, 0.2f, 0.2f), 1.0f, true});
        frame.items.push_back({small, at(4.0), glm::vec3(0.2f, 1.0f, 0.3f), 1.0f, true});
        frame.camera.eye = {0.0, 0.0, 10.0};
        frame.camera.target = {0.0, 0.0, 0.0};
        frame.camera.fov_y_deg = 50.0;
        frame.camera.near = 0.1;
        frame.camera.far = 100.0;
        frame.style = style;
    }
};

TEST(FrameSvg, TechnicalStyleGroupsHiddenLinesByLevel) {
    ThreeCubes scene(Style::technical);
    bz::render::FrameSvgStats stats;
    const std::string doc = bz::render::frame_svg(scene.frame, scene.meshes, 320, 240, {}, &stats);
    // The bar's front long edges: level 1 behind the big cube only (two pieces each), level 2
    // behind both (one each); the bar's back long edges lie behind its own front face too, so
    // behind both cubes they are level 3.
    EXPECT_GE(paths_in(doc, "hidden-1"), 4);
    EXPECT_GE(paths_in(doc, "hidden-2"), 2);
    EXPECT_GE(paths_in(doc, "hidden-3"), 2);
    EXPECT_NE(doc.find("stroke-dasharray=\"6 4\""), std::string::npos);
    EXPECT_NE(doc.find("stroke-width=\"0.75\""), std::string::npos);  // half the 1.5 px ink
    // Every hidden path anchors its dash pattern to its edge.
    const std::regex hidden_path("<path d=\"[^\"]*\"/>");
    const auto h1 = doc.find("<g id=\"hidden-1\"");
    EXPECT_FALSE(std::regex_search(doc.substr(h1), hidden_path));
    EXPECT_EQ(stats.paths,
              static_cast<std::size_t>(paths_in(doc, "silhouette") + paths_in(doc, "crease") +
                                       paths_in(doc, "boundary") + paths_in(doc, "hidden-1") +
                                       paths_in(doc, "hidden-2") + paths_in(doc, "hidden-3")));
    EXPECT_LE(stats.paths, stats.segments);
    EXPECT_LE(stats.travel_after_px, stats.travel_before_px);
}

TEST(FrameSvg, BeamStylesHideHiddenLinesAndColourEachObject) {
    ThreeCubes scene(Style::vector);
    const std::string doc = bz::render::frame_svg(scene.frame, scene.meshes, 320, 240);
    EXPECT_EQ(paths_in(doc, "hidden-1"), -1);
    EXPECT_NE(doc.find("fill=\"#000000\""), std::string::npos);  // the black screen
    // The groups take the first object's green; the big cube's paths name their red.
    EXPECT_NE(doc.find("<g id=\"silhouette\" inkscape:groupmode=\"layer\" inkscape:label=\""
                       "silhouette\" fill=\"none\" stroke=\"#33ff4d\""),
              std::string::npos);
    EXPECT_NE(doc.find("stroke=\"#ff3333\"/>"), std::string::npos);
    // The x-ray style hides nothing and has no hidden groups either: all its lines are level 0.
    scene.frame.style = Style::vector_xray;
    const std::string xray = bz::render::frame_svg(scene.frame, scene.meshes, 320, 240);
    EXPECT_EQ(paths_in(xray, "hidden-1"), -1);
    EXPECT_GT(xray.size(), doc.size());
}

}  // namespace
