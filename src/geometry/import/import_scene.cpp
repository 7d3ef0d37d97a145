#include "geometry/import/import_scene.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/io/regular_file.h"
#include "core/stderr_capture.h"
#include "geometry/import/confined_io.h"
#include "geometry/import/import_failure.h"
#include "geometry/import/import_gltf.h"
#include "geometry/import/import_guard.h"
#include "geometry/import/import_zip.h"

namespace bz::geo::detail {
namespace {

namespace fs = std::filesystem;

// Deeper hierarchies than this are treated as broken files rather than walked.
constexpr std::size_t kMaxNodeDepth = 1024;

std::string lowercase_extension(const fs::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) {
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    }
    return ext;
}

bool inside_any(const fs::path& path, const std::vector<fs::path>& folders) {
    for (const fs::path& folder : folders) {
        auto p = path.begin();
        bool ok = true;
        for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
            if (f->empty() && std::next(f) == folder.end()) break;
            if (p == path.end() || *p != *f) {
                ok = false;
                break;
            }
        }
        if (ok) return true;
    }
    return false;
}

// Everything that can be checked before Assimp allocates anything for the file.
void check_before_import(const fs::path& path, const RegularFile& file,
                         const ImportOptions& options) {
    const ImportLimits& limits = options.limits;
    const std::string ext = lowercase_extension(path);
    const std::string head = read_head(file, kGuardHeadBytes);
    if (auto why = implausible_declared_counts(head, file.size(), ext)) fail_import(path, *why);
    if (looks_like_zip(head)) {
        if (auto why = zip_over_limits(file.fd(), limits.max_unzipped_bytes))
            fail_import(path, *why);
    }
    if (looks_like_glb(head)) {
        if (const auto json_chunk = glb_json_chunk(file.fd(), file.size())) {
            if (auto why = gltf_nodes_over_limit(*json_chunk, limits.max_node_instances)) {
                fail_import(path, *why);
            }
        }
    } else if (ext == ".gltf") {
        const std::string json_text = read_head(file, static_cast<std::size_t>(file.size()));
        if (auto why = gltf_nodes_over_limit(json_text, limits.max_node_instances))
            fail_import(path, *why);
    }
    if (ext == ".obj") {
        if (auto why = too_many_lines(file.fd(), limits.max_text_lines))
            fail_import(path, "OBJ has " + *why);
    }
}

bool has_triangles(const aiMesh& mesh) {
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        if (mesh.mFaces[f].mNumIndices == 3) return true;
    }
    return false;
}

struct Walk {
    const fs::path& path;
    const aiScene& scene;
    const ImportLimits& limits;
    TriMesh out;

    // Appends one placed instance of `mesh`: its vertices transformed, its triangles
    // re-indexed.
    void append_instance(const aiMesh& mesh, const aiMatrix4x4& to_model) {
        if (!mesh.mVertices || !has_triangles(mesh)) return;
        if (out.positions.size() + mesh.mNumVertices > limits.max_triangles ||
            out.triangle_count() + mesh.mNumFaces > limits.max_triangles) {
            fail_import(path, "more than " + std::to_string(limits.max_triangles) +
                                  " triangles or vertices with every node instance placed");
        }
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
            const aiVector3D p = to_model * mesh.mVertices[v];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                const std::string name = mesh.mName.C_Str();
                fail_import(path, "non-finite vertex position (NaN or Inf)" +
                                      (name.empty() ? std::string() : " in mesh '" + name + "'"));
            }
            out.positions.emplace_back(p.x, p.y, p.z);
        }
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines
            for (unsigned k = 0; k < 3; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices)
                    fail_import(path, "vertex index out of range");
                out.indices.push_back(base + face.mIndices[k]);
            }
            // Each aiMesh has one material; a model's meshes become one object, so faces from
            // different meshes keep theirs apart for material boundaries.
            out.face_materials.push_back(mesh.mMaterialIndex);
        }
    }

    void run() {
        struct Visit {
            const aiNode* node;
            aiMatrix4x4 parent;
            std::size_t depth;
        };
        std::vector<Visit> stack{{scene.mRootNode, aiMatrix4x4(), 0}};
        std::uint64_t visited = 0;
        while (!stack.empty()) {
            const Visit at = stack.back();
            stack.pop_back();
            if (at.depth > kMaxNodeDepth) fail_import(path, "node hierarchy too deep");
            // The budget counts instances, so a node reachable along many paths costs each time.
            if (++visited > limits.max_node_instances) {
                fail_import(path, "scene graph has more than " +
                                      std::to_string(limits.max_node_instances) +
                                      " node instances");
            }
            const aiMatrix4x4 to_model = at.parent * at.node->mTransformation;
            for (unsigned i = 0; i < at.node->mNumMeshes; ++i) {
                const unsigned m = at.node->mMeshes[i];
                if (m >= scene.mNumMeshes || !scene.mMeshes[m])
                    fail_import(path, "bad mesh reference");
                append_instance(*scene.mMeshes[m], to_model);
            }
            // Pushed in reverse so children are visited in file order.
            for (unsigned c = at.node->mNumChildren; c-- > 0;) {
                if (at.node->mChildren[c])
                    stack.push_back({at.node->mChildren[c], to_model, at.depth + 1});
            }
        }
    }
};

// The folders an import may read from: `options.allowed_folders`, or the model's own folder.
std::vector<fs::path> allowed_folders_for(const fs::path& path, const ImportOptions& options) {
    if (!options.allowed_folders.empty()) return options.allowed_folders;
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) return {};
    return {resolved.parent_path()};
}

}  // namespace

TriMesh import_in_this_process(const fs::path& path, const ImportOptions& options) {
    RegularFileResult opened = open_regular_file(path);
    if (!opened.why.empty()) fail_import(path, opened.why);
    const RegularFile& file = opened.file;
    if (file.size() > options.limits.max_file_bytes) {
        fail_import(path, "file is " + std::to_string(file.size()) + " bytes, over the limit of " +
                              std::to_string(options.limits.max_file_bytes));
    }
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) fail_import(path, "cannot be resolved: " + ec.message());
    const std::vector<fs::path> folders = allowed_folders_for(path, options);
    if (!inside_any(resolved, folders)) {
        fail_import(path, "lies outside the folders models may be read from");
    }
    check_before_import(path, file, options);

    Assimp::Importer importer;
    auto io = std::make_unique<ConfinedIOSystem>(folders, resolved.parent_path(),
                                                 options.limits.max_file_bytes);
    const ConfinedIOSystem& confined = *io;
    importer.SetIOHandler(io.release());  // the importer owns and deletes it
    // No Assimp::DefaultLogger is ever created, so Assimp logs to its null logger: silent.
    const unsigned flags = aiProcess_Triangulate | aiProcess_ValidateDataStructure;
    const aiScene* scene = nullptr;
    {
        // A few loaders print to stderr directly; keep that out of our one-line messages.
        StderrCapture loader_output;
        try {
            scene = importer.ReadFile(resolved.string(), flags);
        } catch (const std::bad_alloc&) {
            throw;  // the caller says which memory cap was hit
        } catch (const std::exception& e) {
            // Assimp catches its own import errors; this is for the unexpected.
            fail_import(path, std::string("import failed: ") + e.what());
        }
        const std::string printed = loader_output.text();
        // A refused reference fails the import even when the loader carried on without it:
        // the level would otherwise look different from what its author sees.
        if (!confined.refusal().empty()) fail_import(path, confined.refusal());
        if (!scene) {
            std::string why = importer.GetErrorString();
            if (why.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
            if (!printed.empty()) why += " (loader printed: " + printed.substr(0, 200) + ")";
            fail_import(path, why);
        }
    }
    if (!scene->mRootNode) fail_import(path, "no scene hierarchy");
    Walk walk{path, *scene, options.limits, {}};
    walk.run();
    if (walk.out.indices.empty()) fail_import(path, "no triangles");
    return std::move(walk.out);
}

}  // namespace bz::geo::detail
