#include "geometry/vector/svg_document.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using bz::geo::Polyline;
using bz::geo::SvgGroup;

TEST(SvgDocument, FlipsYAndWritesGroupsPathsAndStrokes) {
    SvgGroup g;
    g.id = "silhouette";
    g.stroke = "#33ff4d";
    g.width = 1.5;
    Polyline p;
    p.points = {{0.0, 0.0}, {10.25, 20.0}, {3.0005, 99.9999}};
    g.paths.push_back(p);
    g.path_stroke.push_back("#ff0000");
    SvgGroup h;
    h.id = "hidden-1";
    h.stroke = "#000000";
    h.dash = "4 2";
    h.paths.push_back(p);
    const SvgGroup groups[] = {g, h};
    const std::string doc = bz::geo::svg_document(100, 100, "#000000", groups);
    EXPECT_EQ(doc.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u);
    EXPECT_NE(doc.find("width=\"100\" height=\"100\" viewBox=\"0 0 100 100\""), std::string::npos);
    EXPECT_NE(doc.find("<rect id=\"background\""), std::string::npos);
    // y flipped (100 - y), trailing zeros dropped, 3 decimals kept.
    EXPECT_NE(doc.find("<path d=\"M 0 100 L 10.25 80 3.001 0\" stroke=\"#ff0000\"/>"),
              std::string::npos)
        << doc;
    EXPECT_NE(doc.find("<g id=\"silhouette\" inkscape:groupmode=\"layer\""), std::string::npos);
    EXPECT_NE(doc.find("stroke-width=\"1.5\""), std::string::npos);
    EXPECT_NE(doc.find("stroke-dasharray=\"4 2\""), std::string::npos);
    EXPECT_EQ(doc.substr(doc.size() - 7), "</svg>\n");
}

TEST(SvgDocument, ColoursClampAndKeepTheHueOfHdr) {
    EXPECT_EQ(bz::geo::svg_colour(0.0, 1.0, 0.0), "#00ff00");
    EXPECT_EQ(bz::geo::svg_colour(0.5, 2.0, -1.0), "#40ff00");
    EXPECT_EQ(bz::geo::svg_colour(NAN, 0.0, 0.0), "#000000");
}

}  // namespace
