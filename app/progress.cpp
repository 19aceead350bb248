// progress.cpp: see progress.h.
#include "app/progress.h"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace st {

bool Progress::enabled() {
    if (const char* forced = std::getenv("SHADERTWIN_PROGRESS"); forced && *forced) return forced[0] != '0';
    return isatty(STDERR_FILENO) == 1;
}

Progress::Progress(std::string command, size_t total) : command_(std::move(command)), total_(total) {}

Progress::~Progress() {
    // Leave the terminal's line empty for what comes next.
    if (shown_) std::fputs("\r\033[K", stderr);
}

void Progress::step(const std::string& item) {
    ++done_;
    show(item);
}

void Progress::note(const std::string& text) { show(text); }

void Progress::show(const std::string& text) {
    if (!enabled()) return;
    std::string line = command_ + " " + std::to_string(done_);
    if (total_) line += "/" + std::to_string(total_);
    line += " " + text;
    // \r and erase-to-end: one line, rewritten.
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    std::fflush(stderr);
    shown_ = true;
}

}  // namespace st
