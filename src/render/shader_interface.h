#pragma once
// The numbers the C++ passes and the GLSL stages must agree on, in one place: the per-instance
// layout, the vertex attribute locations, the shader-storage binding points and the texture and
// image units. load_programs injects them into every program as #defines
// (shader_interface_defines(), after #version), so a shader writes INSTANCES_BINDING,
// instance_color(i) (shaders/instance_data.glsl) or TEXTURE_UNIT_DEPTH and never the number;
// the C++ side binds with the same constants. The edge buffer's bindings (lines/edge_buffer.h)
// travel the same way.
//
// Texture units are fixed per sampler at link (`layout(binding = TEXTURE_UNIT_X) uniform
// sampler2D u_x;`), so no pass sets a sampler uniform. A unit only has to differ from the other
// samplers of the same program; tests/render/shader_interface_test.cpp checks that for every
// program and that the GLSL side reads InstanceData as C++ writes it.
#include <cstddef>
#include <string>
#include <vector>

namespace bz::render {

// render::InstanceData (gpu_scene/mesh_cache.h), counted in vec4: the model-view's four
// columns, the colour, the parameters. Read as attributes by the vertex stages that draw a
// mesh and as `vec4 instance_data[]` (binding kInstancesBinding) by the rest.
inline constexpr unsigned kInstanceVec4s = 6;
inline constexpr unsigned kInstanceModelView = 0;  // columns 0-3
inline constexpr unsigned kInstanceColor = 4;
inline constexpr unsigned kInstanceParams = 5;

// Vertex attribute locations of the mesh vertex arrays (MeshCache).
inline constexpr unsigned kAttribPosition = 0;
inline constexpr unsigned kAttribModelView = 1;  // a mat4: locations 1-4
inline constexpr unsigned kAttribColor = 5;
inline constexpr unsigned kAttribParams = 6;
inline constexpr unsigned kAttribNormal = 7;
// The vertex-buffer binding points those attributes read from.
inline constexpr unsigned kVertexBufferPositions = 0;
inline constexpr unsigned kVertexBufferInstances = 1;
inline constexpr unsigned kVertexBufferNormals = 2;

// Shader-storage binding points besides the edge buffer's (lines/edge_buffer.h); one program
// never uses two that share a number.
inline constexpr unsigned kEdgeCosinesBinding = 0;  // lines.geom: 3 crease cosines per triangle
inline constexpr unsigned kInstancesBinding = 1;    // the frame's InstanceData
inline constexpr unsigned kTileListBinding = 6;  // the composite's lit-tile list (tile_list.comp)
inline constexpr unsigned kLitTileCountBinding = 15;   // ... and how many tiles it holds
inline constexpr unsigned kBloomChainBinding = 7;      // bloom_chain.comp's levels past the first
inline constexpr unsigned kEdgeMaterialsBinding = 11;  // lines.geom: material boundary bits
// prepass_raster.comp (lines/prepass_raster.h): the mesh's cluster vertex lists and triangle
// corners, and the frame's work items; it reads positions at kEdgePositionsBinding.
inline constexpr unsigned kRasterVerticesBinding = 12;
inline constexpr unsigned kRasterWorkBinding = 13;
inline constexpr unsigned kRasterCornersBinding = 14;

// Texture units, one per sampler role.
inline constexpr unsigned kTextureUnitDepth = 0;       // the prepass depth (spine test, outlines)
inline constexpr unsigned kTextureUnitSource = 0;      // a bloom step's input
inline constexpr unsigned kTextureUnitCoarser = 0;     // bloom_up: the coarser level
inline constexpr unsigned kTextureUnitLevel = 1;       // bloom_up: this level
inline constexpr unsigned kTextureUnitGlowLast = 2;    // last frame's finished bloom
inline constexpr unsigned kTextureUnitLines = 0;       // the lines target (composites)
inline constexpr unsigned kTextureUnitBloom = 1;       // the finished bloom (composite)
inline constexpr unsigned kTextureUnitTiles = 1;       // screen-tile marks (composite_tiles.vert)
inline constexpr unsigned kTextureUnitMarks = 0;       // lit-tile marks (tile_list.comp)
inline constexpr unsigned kTextureUnitPictureLit = 1;  // last frame's picture marks (tile_list)
inline constexpr unsigned kTextureUnitCanvas = 2;      // the paper canvas (ink_composite)
inline constexpr unsigned kTextureUnitNormals = 1;     // face normals (image outline)
inline constexpr unsigned kTextureUnitProfile = 1;     // stroke profile (halo)
inline constexpr unsigned kTextureUnitOffset = 2;      // smooth offsets (halo)
inline constexpr unsigned kTextureUnitHalo = 3;        // the halo buffer
inline constexpr unsigned kTextureUnitNoise = 1;       // uniform noise (sketch)
inline constexpr unsigned kTextureUnitDepthTiles = 1;  // hierarchical-Z: the fine depth tiles
inline constexpr unsigned kTextureUnitDepthTilesCoarse = 2;  // ... and the coarse ones
inline constexpr unsigned kTextureUnitPeelPrevious = 1;      // occlusion layers: the layer before
// The occlusion layers a line's level is counted from (shaders/lines/occlusion_level.glsl):
// three units from here, clear of every unit a line or stroke stage samples.
inline constexpr unsigned kTextureUnitOcclusionLayer0 = 4;

// Image units.
inline constexpr unsigned kImageUnitPicture = 0;      // the phosphor picture (composite)
inline constexpr unsigned kImageUnitPictureLit = 1;   // its lit-tile marks (composite)
inline constexpr unsigned kImageUnitLitTiles = 2;     // lit_tiles.glsl
inline constexpr unsigned kImageUnitBeamTiles = 3;    // beam_tiles.glsl
inline constexpr unsigned kImageUnitDepthTiles = 0;   // depth_tiles.comp's output
inline constexpr unsigned kImageUnitRasterDepth = 0;  // the compute prepass's depth (R32UI)
inline constexpr unsigned kImageUnitClear = 4;        // clear_image.comp's image
inline constexpr unsigned kImageUnitBloomLevel = 5;   // bloom_chain.comp's output, level 1

// The most levels a mip-chain bloom has (BeamSettings::mip_weights beyond are ignored).
inline constexpr std::size_t kMaxBloomLevels = 12;

// Every constant above and the edge buffer's bindings as "NAME value" for gl::Program: the
// instance indices as uint literals ("6u"), since the shaders index with uints; the rest plain.
const std::vector<std::string>& shader_interface_defines();

}  // namespace bz::render
