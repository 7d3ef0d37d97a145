#pragma once
// A scratch folder for one test, removed with everything in it when the test's ScratchDir goes.
// Its name is the prefix, the process id and a serial number: ctest runs tests in parallel
// processes, and one test may want several folders.
#include <filesystem>
#include <string>
#include <string_view>

namespace bz::test {

class ScratchDir {
  public:
    explicit ScratchDir(std::string_view prefix = "bz_test");
    ~ScratchDir();
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    // The folder, canonical (no links), so tests can compare it with resolved paths.
    const std::filesystem::path& path() const { return path_; }

    // Writes `bytes` to `relative` under the folder (creating folders) and returns its path.
    std::filesystem::path write(const std::string& relative, std::string_view bytes) const;

  private:
    std::filesystem::path path_;
};

}  // namespace bz::test
