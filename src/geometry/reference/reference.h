#pragma once
// The exact CPU reference for the line renderer's visible-spine mask, in double precision.
// It applies the geometry shader's own definitions (feature edges, near/far then guard-band
// clipping, the pixel-crossing rule) but decides visibility by casting rays against every
// occluder triangle instead of reading a depth buffer, so it has no depth precision to lose.
//
// Definitions (see shaders/lines/lines.geom):
//  - A face is front-facing iff dot(n_view, -p0_view) > 0, n = cross(p1 - p0, p2 - p0).
//  - An edge whose neighbour slot marks it non-interior (a_i == v_i) is always a feature edge.
//  - Otherwise, with neighbour U = (v_i, a_i, v_{i+1}): a silhouette iff T is front and U is
//    not; nothing if their facing differs the other way; else a crease iff the object-space unit
//    normals have dot < cos_crease (emitted once, by the face that sees the edge low -> high);
//    failing that, with material_lines, a material boundary when the faces' materials differ.
//  - With intersection_lines, where two occluders' triangles cross (or two of one occluder
//    that share no vertex: geometry/intersect/), the crossing is a line; its own faces are
//    the two triangles it lies on.
//  - A point of an edge is visible iff the segment eye -> point hits no occluder triangle,
//    other than the faces on that edge, whose hit lies at or beyond the near plane and before
//    the point by more than a relative epsilon.
//  - A pixel is lit iff a visible part of an edge crosses its unit square.
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <span>
#include <vector>

#include "geometry/mesh.h"

namespace bz::geo {

struct ReferenceInstance {
    const AdjacencyMesh* mesh = nullptr;
    glm::dmat4 model_view{1.0};  // object -> view space: eye at the origin, looking down -z, y up
    double cos_crease = 0.5;     // cos(60 deg), the renderer's default
    bool occluder = true;        // hides what lies behind it (DrawItem::occluder)
    // Edges between faces of different materials (AdjacencyMesh::material_edges) are lines
    // too, where they are no crease, as long as cos_crease >= -1 (an instance past the
    // creases' distance LOD draws none).
    bool material_lines = false;
    // Takes part in intersection lines (ReferenceOptions::intersection_lines) as long as it is
    // an occluder; off for an instance the renderer draws from its simplified mesh.
    bool intersects = true;
};

struct ReferenceView {
    int width = 0;
    int height = 0;
    double fov_y_deg = 60.0;  // vertical; the aspect ratio is width / height
    double near = 0.1;
    double far = 1000.0;
};

struct ReferenceOptions {
    bool occlusion = true;           // false: every feature edge shows (the arcade style)
    double samples_per_pixel = 4.0;  // visibility samples along each edge, per pixel of length
    int refine_steps = 8;            // bisection steps where visibility changes between samples
    double relative_epsilon = 1e-7;  // a hit at t >= 1 - eps (t = 1 at the point) does not hide
    // Hidden lines too, by occlusion level, up to this level (0: visible lines only; at most
    // kMaxOcclusionLevel, which then stands for "that many or more").
    int hidden_levels = 0;
    // Where the surfaces of two occluding instances (or two faces of one that share no
    // vertex) cross, the crossing is a line too (LineKind::intersection).
    bool intersection_lines = false;
};

// A point's occlusion level: 0 when visible, else the number of surfaces facing the eye that
// lie in front of it (at least 1: a hidden point is behind something), capped here.
inline constexpr int kMaxOcclusionLevel = 3;

// The kinds of feature line, as the geometry shader classifies them. `material` is an edge
// between faces of different materials that is neither a silhouette nor a crease (drawn with
// ReferenceInstance::material_lines; the GPU draws it as a crease flagged material).
// `intersection` is where two surfaces cross (ReferenceOptions::intersection_lines).
enum class LineKind : std::uint8_t { crease, silhouette, boundary, material, intersection };

// One visible stretch of a feature edge, split at its exact visibility changes: window
// coordinates in pixels (OpenGL's: origin at the bottom-left, y up), on or just beyond the
// viewport (the on-screen part, clipped to the viewport grown by 1 px).
struct VisibleSegment {
    glm::dvec2 a{0.0};
    glm::dvec2 b{0.0};
    LineKind kind = LineKind::crease;
    std::uint32_t instance = 0;  // index into the instances given (an intersection: the first)
    std::uint8_t level = 0;      // occlusion level (0: visible); see hidden_levels
    // Window pixels along the edge's on-screen projection from its first end to `a`: a dash
    // pattern that starts there stays fixed to the edge as the camera moves.
    double edge_offset_px = 0.0;
};

struct ReferenceStats {
    std::size_t feature_edges = 0;  // edges found, before clipping
    std::size_t drawn_edges = 0;    // edges left after clipping that touch the viewport
    std::size_t occluder_triangles = 0;
    std::size_t rays = 0;  // visibility queries
    std::size_t lit_pixels = 0;
};

// The visible stretches of every feature edge, in the order the edges are found, and with
// options.hidden_levels > 0 the hidden ones too, split wherever the level changes. The mask
// below is exactly the pixels the visible (level 0) segments cross.
// Throws std::invalid_argument for a null mesh, a size below 1 or a bad view.
std::vector<VisibleSegment> reference_segments(std::span<const ReferenceInstance> instances,
                                               const ReferenceView& view,
                                               const ReferenceOptions& options = {},
                                               ReferenceStats* stats = nullptr);

// Marks the pixels the visible (level 0) `segments` cross (the mask format below); returns
// how many it lit.
std::size_t mark_segments(std::span<const VisibleSegment> segments, int width, int height,
                          std::vector<std::uint8_t>& mask);

// The 8-bit mask (255 = lit), row 0 at the top, width * height bytes. Pixel (x, y) in OpenGL
// window coordinates has its centre at (x + 0.5, y + 0.5) from the bottom-left.
// Throws std::invalid_argument for a null mesh, a size below 1 or a bad view.
std::vector<std::uint8_t> reference_mask(std::span<const ReferenceInstance> instances,
                                         const ReferenceView& view,
                                         const ReferenceOptions& options = {},
                                         ReferenceStats* stats = nullptr);

}  // namespace bz::geo
