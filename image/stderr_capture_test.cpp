// stderr_capture_test.cpp: what a library prints is held back, and a
// broken PNG is refused in one line of ours.
#include "image/stderr_capture.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "image/image_io.h"

namespace st {

TEST(StderrCapture, HoldsBackWhatIsPrinted) {
    std::string held;
    {
        StderrCapture capture;
        std::fprintf(stderr, "libpng error: one\nlibpng error: two\n");
        held = capture.text();
    }
    EXPECT_EQ(held, "libpng error: one\nlibpng error: two\n");
}

TEST(StderrCapture, JoinLines) {
    EXPECT_EQ(join_lines("a\n  b \n\na\nc"), "a; b; c");
    EXPECT_EQ(join_lines(""), "");
}

TEST(ReadImage, ABrokenPngIsOneLine) {
    const std::string path = testing::TempDir() + "shadertwin-broken.png";
    std::ofstream(path, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    try {
        read_image(path);
        FAIL() << "a broken PNG was read";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        EXPECT_EQ(what.rfind("cannot read " + path + ": ", 0), 0u) << what;
    }
    std::remove(path.c_str());
}

}  // namespace st
