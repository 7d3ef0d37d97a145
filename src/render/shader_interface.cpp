#include "render/shader_interface.h"

#include "render/gpu_scene/mesh_cache.h"
#include "render/lines/edge_buffer.h"
#include "render/lines/hiz_culling.h"

namespace bz::render {

// The C++ side of the instance layout: what the constants say is what InstanceData is.
static_assert(sizeof(InstanceData) == kInstanceVec4s * sizeof(glm::vec4));
static_assert(offsetof(InstanceData, model_view) == kInstanceModelView * sizeof(glm::vec4));
static_assert(offsetof(InstanceData, color) == kInstanceColor * sizeof(glm::vec4));
static_assert(offsetof(InstanceData, params) == kInstanceParams * sizeof(glm::vec4));
static_assert(kAttribModelView + 4 <= kAttribColor, "the model-view takes four locations");

namespace {

std::string define(const char* name, unsigned value, const char* suffix = "") {
    return std::string(name) + ' ' + std::to_string(value) + suffix;
}

std::vector<std::string> build_defines() {
    return {
        define("INSTANCE_VEC4S", kInstanceVec4s, "u"),
        define("INSTANCE_MODEL_VIEW", kInstanceModelView, "u"),
        define("INSTANCE_COLOR", kInstanceColor, "u"),
        define("INSTANCE_PARAMS", kInstanceParams, "u"),
        define("ATTRIB_POSITION", kAttribPosition),
        define("ATTRIB_MODEL_VIEW", kAttribModelView),
        define("ATTRIB_COLOR", kAttribColor),
        define("ATTRIB_PARAMS", kAttribParams),
        define("ATTRIB_NORMAL", kAttribNormal),
        define("EDGE_COSINES_BINDING", kEdgeCosinesBinding),
        define("EDGE_MATERIALS_BINDING", kEdgeMaterialsBinding),
        define("INSTANCES_BINDING", kInstancesBinding),
        define("TILE_LIST_BINDING", kTileListBinding),
        define("LIT_TILE_COUNT_BINDING", kLitTileCountBinding),
        define("BLOOM_CHAIN_BINDING", kBloomChainBinding),
        define("EDGE_LIST_BINDING", kEdgeListBinding),
        define("EDGE_POSITIONS_BINDING", kEdgePositionsBinding),
        define("EDGE_RECORDS_BINDING", kEdgeRecordsBinding),
        define("EDGE_COMMAND_BINDING", kEdgeCommandBinding),
        define("EDGE_VERTEX_NORMALS_BINDING", kVertexNormalsBinding),
        define("SPINE_SAMPLES_BINDING", kSpineSamplesBinding),
        define("SPINE_SPANS_BINDING", kSpineSpansBinding),
        define("EDGE_FACE_NORMALS_BINDING", kFaceNormalsBinding),
        define("EDGE_WORK_BINDING", kEdgeWorkBinding),
        define("RASTER_VERTICES_BINDING", kRasterVerticesBinding),
        define("RASTER_WORK_BINDING", kRasterWorkBinding),
        define("RASTER_CORNERS_BINDING", kRasterCornersBinding),
        define("INTERSECTIONS_BINDING", kIntersectionsBinding),
        define("TEXTURE_UNIT_DEPTH", kTextureUnitDepth),
        define("TEXTURE_UNIT_SOURCE", kTextureUnitSource),
        define("TEXTURE_UNIT_COARSER", kTextureUnitCoarser),
        define("TEXTURE_UNIT_LEVEL", kTextureUnitLevel),
        define("TEXTURE_UNIT_GLOW_LAST", kTextureUnitGlowLast),
        define("TEXTURE_UNIT_LINES", kTextureUnitLines),
        define("TEXTURE_UNIT_BLOOM", kTextureUnitBloom),
        define("TEXTURE_UNIT_TILES", kTextureUnitTiles),
        define("TEXTURE_UNIT_MARKS", kTextureUnitMarks),
        define("TEXTURE_UNIT_PICTURE_LIT", kTextureUnitPictureLit),
        define("TEXTURE_UNIT_CANVAS", kTextureUnitCanvas),
        define("TEXTURE_UNIT_NORMALS", kTextureUnitNormals),
        define("TEXTURE_UNIT_PROFILE", kTextureUnitProfile),
        define("TEXTURE_UNIT_OFFSET", kTextureUnitOffset),
        define("TEXTURE_UNIT_HALO", kTextureUnitHalo),
        define("TEXTURE_UNIT_NOISE", kTextureUnitNoise),
        define("TEXTURE_UNIT_DEPTH_TILES", kTextureUnitDepthTiles),
        define("TEXTURE_UNIT_DEPTH_TILES_COARSE", kTextureUnitDepthTilesCoarse),
        define("TEXTURE_UNIT_PEEL_PREVIOUS", kTextureUnitPeelPrevious),
        define("TEXTURE_UNIT_OCCLUSION_LAYER0", kTextureUnitOcclusionLayer0),
        define("TEXTURE_UNIT_OCCLUSION_LAYER1", kTextureUnitOcclusionLayer0 + 1),
        define("TEXTURE_UNIT_OCCLUSION_LAYER2", kTextureUnitOcclusionLayer0 + 2),
        define("IMAGE_UNIT_PICTURE", kImageUnitPicture),
        define("IMAGE_UNIT_PICTURE_LIT", kImageUnitPictureLit),
        define("IMAGE_UNIT_LIT_TILES", kImageUnitLitTiles),
        define("IMAGE_UNIT_BEAM_TILES", kImageUnitBeamTiles),
        define("IMAGE_UNIT_DEPTH_TILES", kImageUnitDepthTiles),
        define("IMAGE_UNIT_RASTER_DEPTH", kImageUnitRasterDepth),
        define("IMAGE_UNIT_CLEAR", kImageUnitClear),
        define("IMAGE_UNIT_BLOOM_LEVEL", kImageUnitBloomLevel),
        define("MAX_BLOOM_LEVELS", static_cast<unsigned>(kMaxBloomLevels)),
        define("DEPTH_TILE_SIZE", static_cast<unsigned>(kDepthTileSize)),
        define("COARSE_DEPTH_TILES", static_cast<unsigned>(kCoarseDepthTiles)),
    };
}

}  // namespace

const std::vector<std::string>& shader_interface_defines() {
    static const std::vector<std::string> defines = build_defines();  // constant once built
    return defines;
}

}  // namespace bz::render
