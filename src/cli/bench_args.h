#pragma once
// The command line of `beamzone bench`: parsed and checked without a model, a level or GL, so
// the fuzz target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "scene/style.h"

namespace bz::app {

extern const char* const kBenchUsage;  // the --help text

enum class BenchMode { single, sweep, scaling, accuracy };

struct BenchOptions {
    std::string level;
    int frames = 300;
    bool frames_given = false;
    int warmup = 30;
    glm::ivec2 size{1280, 720};
    std::string preset;
    std::optional<scene::Style> style;  // none: each frame's own (the level's)
    std::string line_method;            // empty: the level's, else the preset's
    BenchMode mode = BenchMode::single;
    std::string out = "bench-out";
    std::string replay;
    int samples = 6;
    int rounds = 4;
    int series_max = 1'400'000;  // --scaling's model series: sizes up to this many triangles
    std::string timing = "auto";
    std::string beam;
    bool no_phosphor = false;
    // --clears, --prepass-raster, --edge-prefilter; none: the settings' defaults (auto)
    std::optional<render::ColourClears> colour_clears;
    std::optional<render::PrepassRaster> prepass_raster;
    std::optional<render::BloomChain> bloom_chain;  // --bloom-chain
    std::optional<render::EdgePrefilter> edge_prefilter;
    bool size_given = false;
    std::string models_dir = "/usr/share/assimp/models";
    std::vector<std::string> models;
    bool overwrite = false;  // may replace files of another kind named like an output
};

// Throws UsageError naming the bad option.
BenchOptions parse_bench_args(Args args);

}  // namespace bz::app
