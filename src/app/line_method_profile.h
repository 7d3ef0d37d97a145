#pragma once
// The machine's measured crossing between the geometry shader and the compute method
// (render/auto_threshold.h), kept per machine in the cache folder (line-methods.json), so
// it is measured once, not at every start. The key names the GL renderer and version, the
// processor threads llvmpipe may use (LP_NUM_THREADS) and beamzone's version: any of them
// changing means measuring again.
#include <filesystem>
#include <optional>
#include <string>

#include "app/json_text.h"
#include "render/auto_threshold.h"

namespace bz::app {

struct LineMethodProfile {
    std::string machine;  // the cache key
    // Unset: nothing measured; LineMethod::automatic uses its built-in rule.
    std::optional<render::AutoThresholdMeasurement> measurement;
    std::string source;  // "measured now", "measured earlier", or why it is the built-in rule
    // The value for RenderSettings::auto_compute_from_triangles.
    std::optional<std::size_t> threshold() const;
    // One line for logs and reports.
    std::string describe() const;
};

enum class Calibration {
    measure_if_missing,  // play, bench: measure (under a second) when nothing is kept
    kept_only,           // render: a one-off frame uses what is kept, else the built-in rule
};

// The current GL context's profile. `cache`: the kept measurements (the cache folder's
// line-methods.json); a file that does not parse is reported in `source` and never
// overwritten, and a failed write only loses the keeping.
LineMethodProfile line_method_profile(const std::filesystem::path& cache, Calibration calibration);

// line_method_profile with the user's cache folder's line-methods.json (platform::PrefPaths);
// without a usable folder it measures (when asked) without keeping. Prints describe() to stderr
// when it measured.
LineMethodProfile user_line_method_profile(Calibration calibration);

// The machine key: renderer, version, LP_NUM_THREADS and the processor count, beamzone version.
std::string line_method_machine_key(const std::string& gl_renderer, const std::string& gl_version);

// What reports write (summary.json and the rest): the key, source, threshold and both fits.
Json line_method_profile_json(const LineMethodProfile& profile);

// The kept file's text with `profile`'s measurement set under its key, other machines kept;
// `existing` is the file's text ("" when there is none). Throws UserError when it does not parse.
std::string updated_line_method_cache(const std::string& existing,
                                      const LineMethodProfile& profile);
// The measurement kept for `machine` in the file's text, if any. Throws UserError (with the
// parser's position) when the text does not parse or an entry is malformed.
std::optional<render::AutoThresholdMeasurement> kept_measurement(const std::string& text,
                                                                 const std::string& machine);

}  // namespace bz::app
