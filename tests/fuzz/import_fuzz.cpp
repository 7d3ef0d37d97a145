// libFuzzer target for the model import wrapper: any small file of each text format (OBJ,
// PLY, OFF, ASCII STL, glTF) and the containers the wrapper inspects (.glb, zip-based .3mf)
// must give either a mesh or one line naming the file, never a crash, a hang or a sanitizer
// report in this process. The first byte of the input picks the format; the rest is the file.
//
// The checks before Assimp (declared counts, zip directory, glTF node instances, line counts)
// run here in-process, where the fuzzer sees their coverage; then the full wrapper runs the
// import in its child process, as every command does, with a small memory cap and deadline.
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

#include "core/error.h"
#include "core/io/regular_file.h"
#include "geometry/import/import.h"
#include "geometry/import/import_gltf.h"
#include "geometry/import/import_guard.h"
#include "geometry/import/import_zip.h"

namespace {

namespace fs = std::filesystem;

const char* extension_for(char selector) {
    switch (selector) {
        case 'p':
            return ".ply";
        case 'f':
            return ".off";
        case 's':
            return ".stl";
        case 'g':
            return ".gltf";
        case 'b':
            return ".glb";
        case 'z':
            return ".3mf";
        default:
            return ".obj";
    }
}

// A folder per fuzzing process, with files an input may refer to: a material, a buffer, a
// FIFO (must be refused, never opened) and a file outside the folder (must not be read).
const fs::path& work_dir() {
    static const fs::path dir = [] {
        const fs::path root =
            fs::temp_directory_path() / ("bz_import_fuzz_" + std::to_string(::getpid()));
        fs::create_directories(root / "model");
        std::ofstream(root / "model" / "side.mtl") << "newmtl m\nKd 1 0 0\n";
        std::ofstream(root / "model" / "side.bin", std::ios::binary) << std::string(48, '\0');
        std::ofstream(root / "outside.bin", std::ios::binary) << std::string(48, '\x7f');
        ::mkfifo((root / "model" / "fifo").c_str(), 0600);
        return root / "model";
    }();
    return dir;
}

void check_guards(const fs::path& path, const std::string& ext) {
    bz::RegularFileResult opened = bz::open_regular_file(path);
    if (!opened.why.empty()) return;
    const std::string head = bz::read_head(opened.file, bz::geo::detail::kGuardHeadBytes);
    (void)bz::geo::detail::implausible_declared_counts(head, opened.file.size(), ext);
    if (bz::geo::detail::looks_like_zip(head)) {
        (void)bz::geo::detail::zip_over_limits(opened.file.fd(), 1 << 20);
    }
    if (bz::geo::detail::looks_like_glb(head)) {
        if (auto json = bz::geo::detail::glb_json_chunk(opened.file.fd(), opened.file.size())) {
            (void)bz::geo::detail::gltf_nodes_over_limit(*json, 1000);
        }
    } else if (ext == ".gltf") {
        (void)bz::geo::detail::gltf_nodes_over_limit(head, 1000);
    }
    if (ext == ".obj") (void)bz::geo::detail::too_many_lines(opened.file.fd(), 10000);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0 || size > 64 * 1024) return 0;
    const std::string ext = extension_for(static_cast<char>(data[0]));
    const fs::path path = work_dir() / ("input" + ext);
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    }
    check_guards(path, ext);
    bz::geo::ImportOptions options;
    options.allowed_folders = {work_dir()};
    options.limits.memory_bytes = std::uint64_t{1} << 30;
    options.limits.seconds = 5.0;
    options.limits.max_unzipped_bytes = 1 << 20;
    options.limits.max_node_instances = 1000;
    options.limits.max_triangles = 1 << 20;
    try {
        const bz::geo::TriMesh mesh = bz::geo::import_model(path, options);
        // The wrapper's contract: a mesh it returns has triangles and valid indices.
        if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) __builtin_trap();
        for (const std::uint32_t i : mesh.indices) {
            if (i >= mesh.positions.size()) __builtin_trap();
        }
    } catch (const bz::UserError& e) {
        const std::string m = e.what();
        if (m.rfind(path.string() + ": error: ", 0) != 0) __builtin_trap();
        if (m.find('\n') != std::string::npos) __builtin_trap();
    }
    return 0;
}
