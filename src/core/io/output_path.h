#pragma once
// Checks a path a command was told to write to, before any work is done, so that a typo
// cannot destroy something: the folder must exist already (it is never created behind the
// user's back), must take a new file, the path must not name one of the command's inputs, and
// whatever already sits there must be a file of the same kind (a PNG is never written over a
// model, nor a replay over a level) unless the user passed --overwrite. A device, FIFO, socket
// or folder at the path, and an input of the command (compared by device and inode, through
// links), are refused even then. Each refusal throws UserError naming the option, the path and
// the reason. Every command checks every output with these before it starts any work; the
// write itself goes through bz::write_file_atomic, which refuses a non-regular target again
// and keeps an existing file's mode and owner.
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
inline constexpr OutputKind kJsonOutput{"JSON document", "{"};
inline constexpr OutputKind kCsvOutput{"CSV table", "Config,"};
inline constexpr OutputKind kSvgOutput{"SVG document", "<?xml"};

// The kind a file name promises by its extension (.png, .replay, .json, .csv, .svg), or nullptr.
const OutputKind* output_kind_of(const std::filesystem::path& name);

void check_output_file(std::string_view option, const std::filesystem::path& out,
                       const OutputKind& kind, std::span<const std::filesystem::path> inputs,
                       bool overwrite = false);

// A folder the command fills with files (bench --out): its parent must exist, anything already
// at the path must be a writable folder, and every file already in it or in its subfolders
// (`subfolders`, e.g. "masks") whose extension names an output kind passes check_output_file,
// so no input and no file of another kind that carries an output's name is ever replaced.
void check_output_dir(std::string_view option, const std::filesystem::path& out,
                      std::span<const std::filesystem::path> inputs,
                      std::span<const std::string_view> subfolders = {}, bool overwrite = false);

}  // namespace bz
