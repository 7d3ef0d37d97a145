#pragma once
// The command line of `beamzone reference`: parsed and checked without a model, a level or GL, so
// the fuzz target (tests/fuzz/cli_fuzz.cpp) runs this very code.
#include <optional>
#include <string>

#include "cli/camera_options.h"
#include "scene/style.h"

namespace bz::app {

extern const char* const kReferenceUsage;  // the --help text

struct ReferenceOptions {
    std::string input;
    CameraArgs camera;
    std::string level;
    std::optional<double> time;
    scene::Style style = scene::Style::vector;
    double crease = 60.0;
    bool material_lines = false;  // --material-lines: edges between materials are lines too
    // --intersection-lines: where surfaces cross, a line
    bool intersection_lines = false;
    std::string mask = "reference.png";
    std::string svg;         // also the visible lines as SVG
    bool overwrite = false;  // --mask may replace an existing file that is not a PNG
};

// Throws UsageError naming the bad option.
ReferenceOptions parse_reference_args(Args args);

}  // namespace bz::app
