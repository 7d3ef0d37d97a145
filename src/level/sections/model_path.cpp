#include "level/sections/model_path.h"

#include <algorithm>
#include <array>

#include "level/diagnostic.h"

namespace bz::level {
namespace fs = std::filesystem;

namespace {

constexpr std::array<std::string_view, 9> kExtensions = {".obj", ".ply", ".stl", ".off", ".gltf",
                                                         ".glb", ".fbx", ".dae", ".3ds"};

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) {
        return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : static_cast<char>(c);
    });
    return s;
}

fs::path canonical_folder(const fs::path& folder) {
    std::error_code ec;
    fs::path abs = fs::absolute(folder.empty() ? fs::path(".") : folder, ec);
    if (ec) return {};
    fs::path canon = fs::weakly_canonical(abs, ec);
    if (ec) return {};
    return canon;
}

}  // namespace

bool is_model_extension(std::string_view extension) {
    const std::string ext = lowercase(std::string(extension));
    return std::find(kExtensions.begin(), kExtensions.end(), ext) != kExtensions.end();
}

bool is_inside(const fs::path& path, const fs::path& folder) {
    if (folder.empty()) return false;
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        // weakly_canonical keeps a trailing separator as an empty last element.
        if (f->empty() && std::next(f) == folder.end()) break;
        if (p == path.end() || *p != *f) return false;
    }
    return true;
}

ModelRoots model_roots(const fs::path& level_dir, const fs::path& data_root) {
    return {canonical_folder(level_dir), canonical_folder(data_root)};
}

ModelPath resolve_model_path(std::string_view text, const ModelRoots& roots) {
    ModelPath out;
    const std::string shown = quote(text, 80);
    if (text.empty()) {
        out.error = "model path is empty";
        return out;
    }
    if (text.find('\0') != std::string_view::npos) {
        out.error = "model path " + shown + " contains a NUL character";
        return out;
    }
    const fs::path written{std::string(text)};
    if (written.is_absolute() || written.has_root_directory() || written.has_root_name()) {
        out.error = "model path " + shown +
                    " is absolute; write it relative to the level file (for example "
                    "'../data/models/pylon.obj')";
        return out;
    }
    const fs::path& level_folder = roots.level_folder;
    const fs::path& data_folder = roots.data_folder;
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(level_folder / written, ec);
    if (ec || level_folder.empty()) {
        out.error = "model path " + shown + " cannot be resolved: " + ec.message();
        return out;
    }
    out.resolved = resolved;
    if (!is_inside(resolved, level_folder) && !is_inside(resolved, data_folder)) {
        out.error = "model path " + shown +
                    " leads outside the level's folder and the project's data/ folder";
        return out;
    }
    out.watchable = true;
    const auto status = fs::status(resolved, ec);
    if (ec || !fs::exists(status)) {
        out.error =
            "model file " + shown + " not found (looked for " + quote(resolved.string(), 160) + ")";
        return out;
    }
    if (!fs::is_regular_file(status)) {
        out.error = "model path " + shown + " is not a regular file";
        return out;
    }
    if (!is_model_extension(resolved.extension().string())) {
        out.error = "model file " + shown +
                    " has an unsupported extension; use .obj, .ply, .stl, .off, .gltf, .glb, "
                    ".fbx, .dae or .3ds";
        return out;
    }
    return out;
}

}  // namespace bz::level
