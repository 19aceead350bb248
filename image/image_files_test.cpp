// image_files_test.cpp: the writers, hash and error statistics shadertwin
// computes without OpenImageIO (png_file.h, exr_file.h, pixel_hash.h,
// error_stats.h) against the OpenImageIO module they replaced on those
// paths: the same hashes and statistics to the bit, and files it reads back
// with the same pixels and attributes.
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/error_stats.h"
#include "image/exr_file.h"
#include "image/image_library.h"
#include "image/pixel_hash.h"
#include "image/png_file.h"

namespace st {
namespace {

namespace fs = std::filesystem;

// Deterministic floats in [lo, hi) (splitmix64).
std::vector<float> noise(size_t n, uint64_t seed, float lo, float hi) {
    std::vector<float> v(n);
    for (float& x : v) {
        uint64_t z = (seed += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        x = lo + (hi - lo) * float(double((z ^ (z >> 31)) >> 11) * 0x1.0p-53);
    }
    return v;
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ImageFiles, PixelHashIsOpenImageIOs) {
    for (auto [w, h] : {std::pair{1, 1}, std::pair{7, 3}, std::pair{64, 48}, std::pair{333, 211}}) {
        std::vector<float> px = noise(size_t(w) * size_t(h) * 4, uint64_t(w * 1000 + h), -2.0f, 3.0f);
        px[0] = kNaN;
        if (px.size() > 5) px[5] = -kInf;
        EXPECT_EQ(sha1_pixel_hash(px.data(), w, h), image_library().pixel_hash(px.data(), w, h)) << w << "x" << h;
    }
}

void expect_same_stats(const std::vector<float>& a, const std::vector<float>& b, int w, int h, const char* what) {
    const ImageErrorStats ours = error_stats(a.data(), b.data(), w, h);
    const ImageErrorStats oiio = image_library().error_stats(a.data(), b.data(), w, h);
    // Bit for bit, NaN alike: the same sums in the same order.
    auto same = [](double x, double y) { return std::bit_cast<uint64_t>(x) == std::bit_cast<uint64_t>(y) || (x != x && y != y); };
    EXPECT_TRUE(same(ours.max_error, oiio.max_error)) << what << ": max " << ours.max_error << " " << oiio.max_error;
    EXPECT_TRUE(same(ours.mean_error, oiio.mean_error)) << what << ": mean " << ours.mean_error << " " << oiio.mean_error;
    EXPECT_TRUE(same(ours.rms_error, oiio.rms_error)) << what << ": rms " << ours.rms_error << " " << oiio.rms_error;
    EXPECT_TRUE(same(ours.psnr, oiio.psnr)) << what << ": psnr " << ours.psnr << " " << oiio.psnr;
}

TEST(ImageFiles, ErrorStatsAreOpenImageIOs) {
    const int w = 300, h = 50;  // 15,000 pixels: several batches of 4096
    const size_t n = size_t(w) * size_t(h) * 4;
    const std::vector<float> a = noise(n, 1, 0.0f, 1.0f);
    std::vector<float> b = noise(n, 2, 0.0f, 1.0f);
    expect_same_stats(a, b, w, h, "unit range");
    expect_same_stats(a, a, w, h, "identical");
    const std::vector<float> hdr = noise(n, 3, -4.0f, 12.0f);
    expect_same_stats(a, hdr, w, h, "beyond 1");
    // Non-finite values: alike on both sides, then unlike, before and after
    // the first unlike one.
    std::vector<float> x = a, y = b;
    x[10] = y[10] = kNaN;
    x[11] = kInf;
    y[11] = -kInf;
    expect_same_stats(x, y, w, h, "alike non-finite");
    x[100] = kNaN;
    expect_same_stats(x, y, w, h, "one NaN");
    y[20000] = kInf;
    x[40000] = -kInf;
    expect_same_stats(x, y, w, h, "NaN, then infinities");
}

class ImageFilesOnDisk : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("st-image-files-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                            "-" + std::to_string(reinterpret_cast<uintptr_t>(this)));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

const std::map<std::string, std::string> kAttributes{{"shadertwin:commit", "abc123"},
                                                     {"shadertwin:gl_reference", "llvmpipe (LLVM 15), Mesa 22.3.6"}};

// A file read back through the OpenImageIO module.
struct ReadBack {
    bool ok = false;
    int width = 0, height = 0;
    std::vector<float> rgba;
    std::map<std::string, std::string> attributes;
    std::string error;
};
// The attributes a file carries (shadertwin:*), without what the reader
// says of the file itself (file:*).
std::map<std::string, std::string> with_only_ours(std::map<std::string, std::string> attributes) {
    std::erase_if(attributes, [](const auto& a) { return a.first.rfind("file:", 0) == 0; });
    return attributes;
}
ReadBack read_back(const std::string& path) {
    ReadBack r;
    r.ok = image_library().read(path, 1 << 14, r.width, r.height, r.rgba, r.attributes, r.error);
    return r;
}

TEST_F(ImageFilesOnDisk, PngReadsBackWithItsBytesAndAttributes) {
    for (int channels : {3, 4}) {
        const int w = 37, h = 11;
        std::vector<uint8_t> bytes(size_t(w) * size_t(h) * size_t(channels));
        for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = uint8_t((i * 131) ^ (i >> 3));
        // Alpha of every value: the colour reads back as stored, not
        // multiplied by it (OpenImageIO's default for PNG).
        const std::string path = (dir_ / ("t" + std::to_string(channels) + ".png")).string();
        ASSERT_EQ(write_png_file(path, w, h, channels, bytes.data(), kAttributes), "");
        const ReadBack back = read_back(path);
        ASSERT_TRUE(back.ok) << back.error;
        ASSERT_EQ(back.width, w);
        ASSERT_EQ(back.height, h);
        const std::vector<float>& rgba = back.rgba;
        for (size_t p = 0; p < size_t(w) * size_t(h); ++p)
            for (int c = 0; c < 4; ++c) {
                // (OpenImageIO scales bytes to floats its own way: compare bytes.)
                const long want = c < channels ? long(bytes[p * size_t(channels) + size_t(c)]) : 255;
                ASSERT_EQ(std::lround(rgba[p * 4 + size_t(c)] * 255.0f), want) << "pixel " << p << " channel " << c;
            }
        EXPECT_EQ(with_only_ours(back.attributes), kAttributes);
        EXPECT_EQ(back.attributes.at("file:pixel_type"), "uint8");
        EXPECT_EQ(back.attributes.at("file:channels"), std::to_string(channels));
    }
}

TEST_F(ImageFilesOnDisk, ExrReadsBackWithItsFloatsAndAttributes) {
    const int w = 29, h = 13;
    std::vector<float> px = noise(size_t(w) * size_t(h) * 4, 9, -1.0f, 50.0f);
    px[3] = kInf;
    px[8] = 1e-42f;  // a subnormal survives
    const std::string path = (dir_ / "t.exr").string();
    ASSERT_EQ(write_exr_file(path, w, h, px.data(), kAttributes), "");
    const ReadBack back = read_back(path);
    ASSERT_TRUE(back.ok) << back.error;
    ASSERT_EQ(back.width, w);
    ASSERT_EQ(back.height, h);
    const std::vector<float>& rgba = back.rgba;
    for (size_t i = 0; i < px.size(); ++i)
        ASSERT_EQ(std::bit_cast<uint32_t>(rgba[i]), std::bit_cast<uint32_t>(px[i])) << "value " << i;
    EXPECT_EQ(with_only_ours(back.attributes), kAttributes);
    EXPECT_EQ(back.attributes.at("file:pixel_type"), "float");
}

TEST_F(ImageFilesOnDisk, UnwritableFolderIsAnErrorNotACrash) {
    const uint8_t px[4] = {1, 2, 3, 4};
    const float fx[4] = {1, 2, 3, 4};
    EXPECT_NE(write_png_file((dir_ / "no/such/folder/x.png").string(), 1, 1, 4, px, {}), "");
    EXPECT_NE(write_exr_file((dir_ / "no/such/folder/x.exr").string(), 1, 1, fx, {}), "");
}

}  // namespace
}  // namespace st
