#pragma once
// Every budget beamzone enforces on untrusted input, in one place, so each one is stated once
// and checked before the work it bounds starts. The README lists them; a new reader or a new
// knob adds its budget here rather than a private constant beside its code.
#include <cstddef>
#include <cstdint>

namespace bz::budget {

// --- Input files: the most bytes read from one file of each kind (bz::read_file refuses
// a larger one naming the file, before reading it). Regular files only, opened without
// blocking, everywhere.
inline constexpr std::size_t kLevelBytes = std::size_t{1} << 20;          // level .toml
inline constexpr std::size_t kSettingsBytes = std::size_t{1} << 20;       // settings.toml
inline constexpr std::size_t kHighScoreBytes = std::size_t{1} << 20;      // highscores
inline constexpr std::size_t kReplayBytes = std::size_t{256} << 20;       // .replay
inline constexpr std::size_t kGamepadDbBytes = std::size_t{4} << 20;      // gamecontrollerdb.txt
inline constexpr std::size_t kShaderFileBytes = std::size_t{1} << 20;     // one shader file
inline constexpr std::size_t kFontBytes = std::size_t{4} << 20;           // Hershey .jhf font
inline constexpr std::size_t kPngBytes = std::size_t{256} << 20;          // PNG read by compare
inline constexpr std::uintmax_t kModelBytes = std::uintmax_t{512} << 20;  // model files

// --- Shaders: the text one program assembles from its includes, and how deep they nest.
// A file included twice along different paths (a diamond) is pasted once: the include graph
// is walked by resolved path, so its size grows with the files, never exponentially.
inline constexpr std::size_t kShaderAssembledBytes = std::size_t{4} << 20;
inline constexpr int kShaderIncludeDepth = 32;

// --- Scenes: checked by `check` and at load, before any mesh is uploaded, with the level line
// that crosses them. Instances count every placed object; triangles count each instance's
// model once per instance (what the GPU draws); memory is the estimated GPU bytes of the
// distinct meshes (vertex, index and adjacency buffers).
inline constexpr std::int64_t kSceneInstances = 20'000;
inline constexpr std::int64_t kSceneTriangles = 50'000'000;
inline constexpr std::int64_t kSceneGpuBytes = std::int64_t{2} << 30;
// Estimated GPU bytes per triangle of a loaded mesh (positions, normals, adjacency indices).
inline constexpr std::int64_t kGpuBytesPerTriangle = 96;

// --- Command-line knobs.
inline constexpr int kRenderCopies = 10'000;                   // render --copies
inline constexpr std::int64_t kCopiesTriangles = 50'000'000;   // copies x model triangles
inline constexpr int kImageSide = 8192;                        // --size W or H, pixels
inline constexpr std::int64_t kImagePixels = 8192LL * 8192LL;  // W x H

// --- Cameras: the largest coordinate (eye, target, framed bounds, near and far) a picture is
// made at. Squares and sums of squares of it stay finite in single precision, as the GPU's
// matrices need; a model or a camera beyond it is refused with a message, not drawn empty.
inline constexpr double kCameraExtent = 1e15;

// --- Text from untrusted places shown in messages and menus.
inline constexpr std::size_t kMessageValueBytes = 200;  // one value in a message
inline constexpr std::size_t kMenuLabelChars = 40;      // one name in a menu line

}  // namespace bz::budget
