#pragma once
// Redirects file descriptor 2 into a temporary file for the lifetime of the object, so a
// third-party library that prints straight to stderr (some Assimp loaders do) cannot break the
// "one line per error" promise. text() returns what was captured; the caller decides whether
// to fold it into its own message.
#include <string>

namespace bz {

class StderrCapture {
  public:
    StderrCapture();
    ~StderrCapture();
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;
    // Restores stderr (if not yet) and returns the captured text, whitespace-collapsed.
    std::string text();

  private:
    void restore();
    int saved_fd_ = -1;
    int capture_fd_ = -1;
};

}  // namespace bz
