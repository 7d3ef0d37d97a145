#pragma once
// The only way Assimp reaches the file system during an import: every file a loader opens or
// probes (the model itself, an OBJ's mtllib, glTF buffer uris, a 3MF's zip, ...) must resolve,
// `..` and symbolic links included, inside one of the allowed folders, be a regular file
// (opened without blocking, so a FIFO cannot hang the import) and be within the size limit.
// A file that is opened but refused is remembered, so the import can fail with a message
// naming the model, the reference and the reason, even when the loader itself would have
// carried on. A mere probe (Exists) outside the folders answers "no" without failing the
// import: some loaders probe guesses (LWS looks for its objects in "../").
#include <assimp/IOSystem.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace bz::geo::detail {

class ConfinedIOSystem final : public Assimp::IOSystem {
  public:
    // Relative names are taken relative to `base_folder` (the model's own folder), not to
    // the process's working folder, which has nothing to do with the model.
    ConfinedIOSystem(std::vector<std::filesystem::path> allowed_folders,
                     std::filesystem::path base_folder, std::uintmax_t max_file_bytes);

    bool Exists(const char* file) const override;
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
    void Close(Assimp::IOStream* stream) override;

    // The first refusal ("reference 'X': reason"), empty when nothing was refused.
    const std::string& refusal() const { return refusal_; }

  private:
    // Where `file` leads, and why it may not be read (empty when it may).
    struct Checked {
        std::filesystem::path resolved;
        std::string why;
    };
    Checked check(const char* file) const;
    void refuse(const char* file, const std::string& why) const;

    std::vector<std::filesystem::path> allowed_;
    std::filesystem::path base_;
    std::uintmax_t max_file_bytes_;
    mutable std::string refusal_;
};

}  // namespace bz::geo::detail
