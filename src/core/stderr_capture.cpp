#include "core/stderr_capture.h"

#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace bz {

StderrCapture::StderrCapture() {
    std::fflush(stderr);
    char name[] = "/tmp/beamzone-stderr-XXXXXX";
    capture_fd_ = mkstemp(name);
    if (capture_fd_ < 0) return;
    unlink(name);
    saved_fd_ = dup(2);
    if (saved_fd_ < 0 || dup2(capture_fd_, 2) < 0) {
        close(capture_fd_);
        capture_fd_ = -1;
    }
}

StderrCapture::~StderrCapture() {
    restore();
    if (capture_fd_ >= 0) close(capture_fd_);
}

void StderrCapture::restore() {
    if (saved_fd_ < 0) return;
    std::fflush(stderr);
    dup2(saved_fd_, 2);
    close(saved_fd_);
    saved_fd_ = -1;
}

std::string StderrCapture::text() {
    restore();
    std::string out;
    if (capture_fd_ < 0) return out;
    lseek(capture_fd_, 0, SEEK_SET);
    char buf[4096];
    ssize_t n = 0;
    while (out.size() < 4096 && (n = read(capture_fd_, buf, sizeof buf)) > 0) {
        out.append(buf, static_cast<std::size_t>(n));
    }
    std::string collapsed;
    for (char c : out) {
        const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
        if (space && (collapsed.empty() || collapsed.back() == ' ')) continue;
        collapsed.push_back(space ? ' ' : c);
    }
    while (!collapsed.empty() && collapsed.back() == ' ') collapsed.pop_back();
    return collapsed;
}

}  // namespace bz
