#pragma once
// Checks a path a command was told to write to, before any work is done, so that a typo
// cannot destroy something: the folder must exist already (it is never created behind the
// user's back), must take a new file, the path must not name one of the command's inputs, and
// whatever already sits there must be a file of the same kind (a PNG is never written over a
// model, nor a replay over a level). Each refusal throws UserError naming the option, the path
// and the reason.
#include <filesystem>
#include <span>
#include <string_view>

namespace bz {

struct OutputKind {
    std::string_view name;   // for messages: "PNG image"
    std::string_view magic;  // how such a file begins; an existing file must begin so too
};

inline constexpr OutputKind kPngOutput{"PNG image", "\x89PNG\r\n\x1a\n"};
inline constexpr OutputKind kReplayOutput{"beamzone replay", "beamzone-replay "};

void check_output_file(std::string_view option, const std::filesystem::path& out,
                       const OutputKind& kind, std::span<const std::filesystem::path> inputs);

// A folder the command fills with files (bench --out): its parent must exist, and anything
// already at the path must be a folder.
void check_output_dir(std::string_view option, const std::filesystem::path& out);

}  // namespace bz
