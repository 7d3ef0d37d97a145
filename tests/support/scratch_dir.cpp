#include "support/scratch_dir.h"

#include <unistd.h>

#include <atomic>
#include <fstream>

namespace bz::test {

ScratchDir::ScratchDir(std::string_view prefix) {
    static std::atomic<int> serial{0};
    // Short: messages quote a long path with its middle cut out (a model reference: 120 bytes).
    const std::string name =
        std::string(prefix) + "_" + std::to_string(::getpid()) + "_" + std::to_string(serial++);
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
    path_ = std::filesystem::canonical(path_);
}

ScratchDir::~ScratchDir() {
    std::error_code ec;  // a test that failed half-way must not throw from here
    std::filesystem::remove_all(path_, ec);
}

std::filesystem::path ScratchDir::write(const std::string& relative, std::string_view bytes) const {
    const std::filesystem::path p = path_ / relative;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return p;
}

}  // namespace bz::test
