// stderr_capture.h: holds back what a library prints on the process's
// standard error while an object of this class lives (libpng prints its own
// "libpng error: ..." lines before OpenImageIO returns the same message as
// an error), so that a refused image is reported in one line of ours.
//
// The redirection is of file descriptor 2 for the whole process: hold it
// only around a library call made while no other thread of ours prints.
#pragma once

#include <string>

namespace st {

class StderrCapture {
public:
    StderrCapture();
    ~StderrCapture();  // restores stderr; what was held back is dropped
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    // What was printed so far, newlines and all.
    std::string text() const;

private:
    int saved_fd_ = -1;    // the real stderr, or -1 when nothing is captured
    int capture_fd_ = -1;  // an unlinked temporary file
};

// A library's multi-line message as one line: lines trimmed, empty and
// repeated lines dropped, the rest joined with "; ".
std::string join_lines(const std::string& text);

}  // namespace st
