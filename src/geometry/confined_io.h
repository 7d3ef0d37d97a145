#pragma once
// The only way Assimp reaches the file system during an import: every file a loader opens or
// probes (the model itself, an OBJ's mtllib, glTF buffer uris, a 3MF's zip, ...) must resolve,
// `..` and symbolic links included, inside one of the allowed folders, be a regular file
// (opened without blocking, so a FIFO cannot hang the import) and be within the size limit.
// Anything else is refused and remembered, so the import can fail with a message naming the
// model, the reference and the reason, even when the loader itself would have carried on.
#include <assimp/IOSystem.hpp>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace bz::geo::detail {

class ConfinedIOSystem final : public Assimp::IOSystem {
  public:
    ConfinedIOSystem(std::vector<std::filesystem::path> allowed_folders,
                     std::uintmax_t max_file_bytes);

    bool Exists(const char* file) const override;
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;
    void Close(Assimp::IOStream* stream) override;

    // The first refusal ("reference 'X': reason"), empty when nothing was refused.
    const std::string& refusal() const { return refusal_; }

  private:
    // Empty when `file` may be read; otherwise why not. Records the first refusal.
    std::string check(const char* file) const;

    std::vector<std::filesystem::path> allowed_;
    std::uintmax_t max_file_bytes_;
    mutable std::string refusal_;
};

}  // namespace bz::geo::detail
