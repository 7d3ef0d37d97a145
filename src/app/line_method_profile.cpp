#include "app/line_method_profile.h"

#include <cstdio>
#include <cstdlib>
#include <thread>

#include "core/error.h"
#include "core/io/file_io.h"
#include "gl/driver.h"
#include "platform/pref_paths.h"

namespace bz::app {

namespace {

constexpr int kFormat = 1;
constexpr std::size_t kMaxCacheBytes = 1u << 20;  // a few hundred machines at most

Json cost_json(const render::MethodCost& c) {
    Json j = Json::object();
    j["fixed_ms"] = c.fixed_ms;
    j["per_1k_triangles_ms"] = c.per_1k_ms;
    return j;
}

Json measurement_json(const render::AutoThresholdMeasurement& m) {
    Json j = Json::object();
    j["compute_from_triangles"] = m.compute_from_triangles == render::kNeverCompute
                                      ? Json(nullptr)
                                      : Json(m.compute_from_triangles);
    j["geometry_shader"] = cost_json(m.geometry_shader);
    j["compute"] = cost_json(m.compute);
    j["calibration_triangles"] = m.sizes;
    // Each size's fastest frame, per method: the points the two lines were fitted through.
    j["calibration_ms"] = {{"geometry_shader", m.geometry_shader_ms}, {"compute", m.compute_ms}};
    j["seconds"] = m.seconds;
    return j;
}

double number_at(const Json& j, const char* key, const std::string& where) {
    if (!j.contains(key) || !j.at(key).is_number())
        throw UserError(where + ": \"" + key + "\" is missing or not a number");
    return j.at(key).get<double>();
}

render::MethodCost cost_from(const Json& j, const char* key, const std::string& where) {
    if (!j.contains(key) || !j.at(key).is_object())
        throw UserError(where + ": \"" + key + "\" is missing or not an object");
    const std::string inner = where + "." + key;
    return {number_at(j.at(key), "fixed_ms", inner),
            number_at(j.at(key), "per_1k_triangles_ms", inner)};
}

Json parse_cache(const std::string& text) {
    try {
        Json j = Json::parse(text);
        if (!j.is_object() || !j.contains("machines") || !j.at("machines").is_object())
            throw UserError("expected an object with a \"machines\" object");
        return j;
    } catch (const nlohmann::json::parse_error& e) {
        // The parser's message names the line and column.
        throw UserError(e.what());
    }
}

}  // namespace

std::optional<std::size_t> LineMethodProfile::threshold() const {
    if (!measurement) return std::nullopt;
    return measurement->compute_from_triangles;
}

std::string LineMethodProfile::describe() const {
    if (!measurement) return "auto line method: built-in rule (" + source + ")";
    const render::AutoThresholdMeasurement& m = *measurement;
    char line[320];
    const std::string from = m.compute_from_triangles == render::kNeverCompute
                                 ? std::string("never")
                                 : std::to_string(m.compute_from_triangles) + " triangles";
    std::snprintf(line, sizeof line,
                  "auto line method: compute from %s (%s; geometry shader %.2f ms + %.3f ms/1k "
                  "triangles, compute %.2f ms + %.3f ms/1k)",
                  from.c_str(), source.c_str(), m.geometry_shader.fixed_ms,
                  m.geometry_shader.per_1k_ms, m.compute.fixed_ms, m.compute.per_1k_ms);
    return line;
}

std::string line_method_machine_key(const std::string& gl_renderer, const std::string& gl_version) {
    const char* threads = std::getenv("LP_NUM_THREADS");
    return gl_renderer + " | " + gl_version +
           " | LP_NUM_THREADS=" + (threads ? std::string(threads) : std::string("unset")) + " | " +
           std::to_string(std::thread::hardware_concurrency()) + " processors | beamzone " +
           BEAMZONE_VERSION;
}

std::optional<render::AutoThresholdMeasurement> kept_measurement(const std::string& text,
                                                                 const std::string& machine) {
    const Json j = parse_cache(text);
    const Json& machines = j.at("machines");
    if (!machines.contains(machine)) return std::nullopt;
    const Json& e = machines.at(machine);
    const std::string where = "machines[\"" + machine + "\"]";
    if (!e.is_object()) throw UserError(where + ": not an object");
    render::AutoThresholdMeasurement m;
    const Json& from =
        e.contains("compute_from_triangles") ? e.at("compute_from_triangles") : Json();
    if (from.is_null()) {
        m.compute_from_triangles = render::kNeverCompute;
    } else if (from.is_number_unsigned()) {
        m.compute_from_triangles = from.get<std::size_t>();
    } else {
        throw UserError(where + ": \"compute_from_triangles\" must be a whole number or null");
    }
    m.geometry_shader = cost_from(e, "geometry_shader", where);
    m.compute = cost_from(e, "compute", where);
    return m;
}

std::string updated_line_method_cache(const std::string& existing,
                                      const LineMethodProfile& profile) {
    Json j = existing.empty() ? Json::object() : parse_cache(existing);
    if (existing.empty()) {
        j["format"] = kFormat;
        j["machines"] = Json::object();
    }
    if (profile.measurement)
        j["machines"][profile.machine] = measurement_json(*profile.measurement);
    return j.dump(2) + "\n";
}

Json line_method_profile_json(const LineMethodProfile& profile) {
    Json j = Json::object();
    j["machine"] = profile.machine;
    j["source"] = profile.source;
    j["measurement"] = profile.measurement ? measurement_json(*profile.measurement) : Json(nullptr);
    return j;
}

LineMethodProfile line_method_profile(const std::filesystem::path& cache, Calibration calibration) {
    LineMethodProfile p;
    p.machine = line_method_machine_key(gl::renderer_name(), gl::version_name());
    std::string text;
    bool cache_usable = true;
    std::error_code ec;
    if (std::filesystem::exists(cache, ec)) {
        try {
            text = read_file(cache, kMaxCacheBytes);
            p.measurement = kept_measurement(text, p.machine);
            if (p.measurement) {
                p.source = "measured earlier, kept in " + cache.string();
                return p;
            }
        } catch (const UserError& e) {
            // Never overwrite what the user may have made by hand.
            cache_usable = false;
            p.source = cache.string() + ": " + e.what() + "; not kept";
        }
    }
    if (calibration == Calibration::kept_only) {
        if (p.source.empty())
            p.source = "not measured on this machine yet: play or bench measure it";
        return p;
    }
    p.measurement = render::measure_auto_threshold();
    if (!cache_usable) {
        p.source = "measured now; " + p.source;
        return p;
    }
    p.source = "measured now";
    try {
        // The cache folder (~/.cache/beamzone) may not exist yet.
        if (cache.has_parent_path()) std::filesystem::create_directories(cache.parent_path());
        write_file_atomic(cache, updated_line_method_cache(text, p));
        p.source += ", kept in " + cache.string();
    } catch (const std::exception& e) {
        p.source += std::string(", not kept: ") + e.what();
    }
    return p;
}

LineMethodProfile user_line_method_profile(Calibration calibration) {
    std::filesystem::path cache;
    std::string no_folder;
    try {
        cache = platform::pref_paths().line_methods;
    } catch (const UserError& e) {
        no_folder = e.what();
    }
    LineMethodProfile p;
    if (!cache.empty()) {
        p = line_method_profile(cache, calibration);
    } else {
        p.machine = line_method_machine_key(gl::renderer_name(), gl::version_name());
        p.source = "no preference folder (" + no_folder + ")";
        if (calibration == Calibration::measure_if_missing) {
            p.measurement = render::measure_auto_threshold();
            p.source = "measured now, not kept: " + p.source;
        }
    }
    if (p.source.rfind("measured now", 0) == 0)
        std::fprintf(stderr, "beamzone: %s\n", p.describe().c_str());
    return p;
}

}  // namespace bz::app
