#pragma once
// The images and buffers a frame's passes read and write, by name. Each pass of a frame's list
// (frame_passes.h) declares its own; the renderer allocates the targets the list names
// (make_targets) and the history the list keeps (frame_history.h), and a pass asks what ran
// before it in this frame (FrameResources::written) instead of reading a flag another pass set.
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace bz::render {

enum class Resource : std::uint8_t {
    depth,         // Targets::depth: the prepass's or the fill's depth
    normals,       // Targets::normals: LineMethod::image_outline's face normals
    edges,         // EdgeStorage: the feature-edge records (and their spine samples)
    lines,         // Targets::lines: HDR beam lines (+ HUD), or the filled styles' HUD
    beam_tiles,    // Targets::beam_tiles: the screen tiles the beam lights, cleared per frame
    bloom_chain,   // Targets::bloom_a/b or bloom_mips: the bloom's working levels
    bloom_out,     // Targets::bloom_out: this frame's finished bloom
    lit_tiles,     // Targets::lit_tiles: the sparse composite's marks
    tile_list,     // Targets::tile_list: the lit tiles to shade, behind their draw command
    canvas,        // Targets::canvas: the filled styles' paper
    shrunk_depth,  // Targets::shrunk_depth: the halo's depth mask
    halo,          // Targets::halo: the halo's off-screen soft halos
    mask,          // Targets::mask: the 1-pixel accuracy mask
    depth_tiles,   // Targets::depth_tiles(_coarse): hierarchical-Z culling's farthest depths
    peel_layers,   // Targets::occlusion_layers: the nearest surfaces facing the eye, peeled
    target,        // the frame's destination: the window or Targets::output
    // History (FrameHistory): kept from one frame to the next.
    phosphor,     // the phosphor picture, updated in place by the composite
    picture_lit,  // the lit tiles of the phosphor picture
    glow,         // last frame's finished bloom, decayed with the phosphor
    picture,      // the last frame's beam picture (lines or phosphor), which a held frame shows
};
inline constexpr int kResourceCount = static_cast<int>(Resource::picture) + 1;

// Whether a resource outlives its frame (FrameHistory holds it).
constexpr bool is_history(Resource r) {
    return r >= Resource::phosphor;
}

std::string_view resource_name(Resource r);

// A set of resources: what a pass reads or writes, what a list needs allocated.
class ResourceSet {
  public:
    constexpr ResourceSet() = default;
    constexpr ResourceSet(std::initializer_list<Resource> rs) {
        for (Resource r : rs) bits_ |= bit(r);
    }
    constexpr bool has(Resource r) const { return (bits_ & bit(r)) != 0; }
    constexpr bool empty() const { return bits_ == 0; }
    constexpr ResourceSet& add(Resource r) {
        bits_ |= bit(r);
        return *this;
    }
    constexpr ResourceSet& add(ResourceSet s) {
        bits_ |= s.bits_;
        return *this;
    }
    constexpr bool contains(ResourceSet s) const { return (bits_ & s.bits_) == s.bits_; }
    friend constexpr ResourceSet operator|(ResourceSet a, ResourceSet b) { return a.add(b); }
    friend constexpr bool operator==(ResourceSet a, ResourceSet b) = default;

  private:
    static constexpr std::uint32_t bit(Resource r) { return 1u << static_cast<unsigned>(r); }
    std::uint32_t bits_ = 0;
};
static_assert(kResourceCount <= 32);

// What this frame's passes have written so far: the renderer adds each pass's declared writes
// after it ran. A pass that may use an image only when an earlier pass of the same frame made
// it (the bloom's sparse downsample over the beam's tile marks, the composite over the list
// of lit tiles) asks here.
struct FrameResources {
    ResourceSet written;
    bool has(Resource r) const { return written.has(r); }
};

}  // namespace bz::render
