// stderr_capture.cpp: see stderr_capture.h.
#include "image/stderr_capture.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <sstream>
#include <vector>

namespace st {

StderrCapture::StderrCapture() {
    std::fflush(stderr);
    capture_fd_ = open("/tmp", O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (capture_fd_ < 0) return;  // nothing held back, but nothing lost either
    saved_fd_ = dup(2);
    if (saved_fd_ < 0 || dup2(capture_fd_, 2) < 0) {
        if (saved_fd_ >= 0) close(saved_fd_);
        saved_fd_ = -1;
    }
}

StderrCapture::~StderrCapture() {
    std::fflush(stderr);
    if (saved_fd_ >= 0) {
        dup2(saved_fd_, 2);
        close(saved_fd_);
    }
    if (capture_fd_ >= 0) close(capture_fd_);
}

std::string StderrCapture::text() const {
    if (saved_fd_ < 0) return {};
    std::fflush(stderr);
    std::string out;
    char buffer[4096];
    off_t at = 0;
    for (ssize_t n; (n = pread(capture_fd_, buffer, sizeof buffer, at)) > 0 && out.size() < (1 << 16); at += n)
        out.append(buffer, size_t(n));
    return out;
}

std::string join_lines(const std::string& text) {
    std::vector<std::string> kept;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos) continue;
        line = line.substr(first, line.find_last_not_of(" \t\r") - first + 1);
        bool seen = false;
        for (const std::string& k : kept) seen = seen || k == line;
        if (!seen) kept.push_back(line);
    }
    std::string out;
    for (const std::string& k : kept) out += (out.empty() ? "" : "; ") + k;
    return out;
}

}  // namespace st
