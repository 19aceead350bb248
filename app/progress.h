// progress.h: what a long command is doing (report, sweeps, bench,
// optics-figures, Monte Carlo), shown on a terminal only: one stderr line
// rewritten in place ("report 12/239 relief-bloom"). Piped or redirected,
// as in CI logs, nothing is printed, so a log holds results and errors
// only. SHADERTWIN_PROGRESS=1 shows it anyway, =0 never.
#pragma once

#include <cstddef>
#include <string>

namespace st {

class Progress {
public:
    // `total` 0: the count is not known.
    Progress(std::string command, size_t total);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    // The next item begins.
    void step(const std::string& item);
    // The same item, further on ("37 %").
    void note(const std::string& text);

    static bool enabled();

private:
    void show(const std::string& text);

    std::string command_;
    size_t total_, done_ = 0;
    bool shown_ = false;
};

}  // namespace st
