#include "level/loader.h"

#include <tuple>

#include "core/error.h"
#include "core/io/file_io.h"
#include "core/text/printable.h"
#include "level/sections/sections.h"
#include "level/sections/table_reader.h"
#include "level/syntax/syntax.h"

namespace bz::level {
namespace fs = std::filesystem;

namespace {

bool before(const toml::source_position& a, const toml::source_position& b) {
    return std::tie(a.line, a.column) < std::tie(b.line, b.column);
}

// The format version must be present and come first, so a reader can tell which rules apply
// before anything else. Returns false when the version is one this build cannot read.
bool check_version(const toml::table& root, Level& level, Diagnostics& diag) {
    const toml::key* first = nullptr;
    for (const auto& [key, value] : root) {
        if (!first || before(key.source().begin, first->source().begin)) first = &key;
    }
    const toml::node* node = root.get("version");
    if (!node) {
        const SourcePos at = first ? diag.at(first->source()) : SourcePos{diag.file(), 1, 1};
        diag.error(at, "the file must start with the format version: version = " +
                           std::to_string(kFormatVersion));
        return true;
    }
    const auto* number = node->as_integer();
    if (!number) {
        diag.error(node->source(),
                   "'version' must be a whole number, not " + std::string(type_name(*node)));
        return false;
    }
    if (number->get() != kFormatVersion) {
        diag.error(node->source(), "unsupported format version " + std::to_string(number->get()) +
                                       "; this beamzone reads version " +
                                       std::to_string(kFormatVersion));
        return false;
    }
    if (first && first->str() != "version") {
        diag.error(node->source(), "'version' must be the first key in the file (it comes after " +
                                       quote(first->str()) + " here)");
    }
    level.version = kFormatVersion;
    return true;
}

void read_identity(TableReader& root, Level& level) {
    if (!root.has("name")) {
        root.missing("name");
    } else if (auto v = root.text("name", 64)) {
        if (v->empty()) {
            root.diagnostics().error(root.get("name")->source(), "'name' must not be empty");
        }
        level.name = *v;
    }
    if (auto v = root.text("author", 64)) level.author = *v;
    if (auto v = root.text("description", 300)) level.description = *v;
    if (auto v = root.boolean("listed")) level.listed = *v;
    if (auto v = root.integer("menu_order", 0, kMaxMenuOrder))
        level.menu_order = static_cast<int>(*v);
}

}  // namespace

LoadResult load_level_string(std::string_view text, const fs::path& file_for_messages,
                             const LoadOptions& options) {
    LoadResult result;
    const std::string file = file_for_messages.string();
    result.dependencies.push_back(file_for_messages);
    if (text.size() > options.max_file_bytes) {
        result.errors.push_back(
            {SourcePos{file, 1, 1}, "file is " + std::to_string(text.size()) +
                                        " bytes, over the limit of " +
                                        std::to_string(options.max_file_bytes)});
        return result;
    }
    SyntaxResult syntax = parse_toml(text, file, options.max_errors);
    if (!syntax.table) {
        result.errors = std::move(syntax.errors);
        return result;
    }
    const toml::table& root = *syntax.table;
    Diagnostics diag(file, options.max_errors);
    Level level;
    level.file = file_for_messages;
    if (check_version(root, level, diag)) {
        TableReader top(root, "the top level", detail::root_keys(), diag);
        // The root table's own position is the whole document; "missing name" belongs at the top.
        read_identity(top, level);
        glm::vec3 obstacle_color = ObjectDesc{}.color;
        detail::ReadContext ctx{diag, options,
                                model_roots(file_for_messages.parent_path(), options.data_root),
                                result.dependencies};
        for (const auto& folder : {ctx.model_roots.level_folder, ctx.model_roots.data_folder}) {
            if (!folder.empty()) level.model_folders.push_back(folder);
        }
        detail::read_field(root, level, obstacle_color, ctx);
        detail::read_player(root, level, ctx);
        detail::read_enemies(root, level, ctx);
        detail::read_backdrop(root, level, ctx);
        detail::read_render(root, level, diag);
        detail::read_obstacles(root, level, obstacle_color, ctx);
        detail::read_camera_path(root, level, ctx);
    }
    result.errors = diag.take();
    sort_by_position(result.errors);
    if (result.errors.empty()) result.level = std::move(level);
    return result;
}

LoadResult load_level_file(const fs::path& file, const LoadOptions& options) {
    std::string text;
    try {
        text = read_file(file, options.max_file_bytes);
    } catch (const UserError& e) {
        // read_file names the file itself; keep only what went wrong.
        std::string why = e.what();
        const std::string prefix = printable(file.string()) + ": ";
        if (why.compare(0, prefix.size(), prefix) == 0) why.erase(0, prefix.size());
        LoadResult result;
        result.dependencies.push_back(file);
        // A problem with the file as a whole is reported at 1:1, so every message has the same
        // file:line:col shape for editors and scripts that parse them.
        result.errors.push_back({SourcePos{file.string(), 1, 1}, why});
        return result;
    }
    return load_level_string(text, file, options);
}

fs::path default_level_path() {
    return levels_dir() / "classic.toml";
}

}  // namespace bz::level
