// texture_files_test.cpp: a scene's texture from image files holds the
// files' texels as the fields say (flipped upright or as stored, sRGB
// decoded or not, grey expanded), is found beside the scene wherever the
// tool runs, and every bad file is refused with a line naming the field
// and the file.
#include "scene/texture_files.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "image/image_io.h"
#include "texture/srgb.h"
#include "scene/input_error.h"
#include "scene/scene.h"
#include "scene/scene_sources.h"
#include "scene/texture_patterns.h"

namespace st {
namespace {

namespace fs = std::filesystem;

class TextureFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("st-texture-files-" + std::to_string(::getpid()));
        fs::create_directories(dir_ / "maps");
        // 2x2 RGBA, top row first: red-ish, green-ish / blue-ish, grey.
        const unsigned char bytes[16] = {255, 0, 0, 255, 0, 128, 0, 200, 0, 0, 64, 255, 128, 128, 128, 0};
        write_png_bytes((dir_ / "maps" / "rgba.png").string(), 2, 2, 4, bytes);
        Image hdr;
        hdr.width = 2, hdr.height = 1;
        hdr.rgba = {4.5f, -1.0f, 0.25f, 1.0f, 100.0f, 0.5f, 0.0f, 0.5f};
        write_exr((dir_ / "maps" / "hdr.exr").string(), hdr, {});
        const unsigned char small[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
        write_png_bytes((dir_ / "maps" / "small.png").string(), 2, 2, 3, small);
        write_png_bytes((dir_ / "maps" / "wide.png").string(), 4, 1, 3, small);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    // A conformance scene sampling `texture` (fields beside sampler "tex"),
    // written beside the maps folder and loaded from there.
    Texture load(nlohmann::json texture) {
        nlohmann::json doc = read_builtin("conformance-file-png-srgb-rgba8");
        texture["sampler"] = "tex";
        doc["textures"] = nlohmann::json::array({texture});
        const fs::path path = dir_ / "scene.json";
        std::ofstream(path) << doc.dump();
        const Scene scene = load_scene(path.string(), {});
        return scene.frame.passes.back().draws.front().textures.front();
    }
    static nlohmann::json read_builtin(const std::string& name) {
        std::ifstream in(SceneSources().find(name)->path);
        return nlohmann::json::parse(in);
    }
    // The InputError's line for a texture.
    std::string refusal(nlohmann::json texture) {
        try {
            load(std::move(texture));
        } catch (const InputError& e) {
            return e.what();
        }
        return "(taken)";
    }

    fs::path dir_;
};

TEST_F(TextureFiles, A2DFileIsFlippedUprightAndDecodedFromSrgb) {
    const Texture t = load({{"pattern", "file"}, {"file", "maps/rgba.png"}});
    ASSERT_EQ(t.width, 2);
    ASSERT_EQ(t.height, 2);
    ASSERT_EQ(t.format, TextureFormat::RGBA32F);
    ASSERT_EQ(t.texels32.size(), 16u);
    // Row 0 (t near 0) is the file's bottom row: blue-ish, then grey.
    EXPECT_EQ(t.texels32[2], float(srgb_to_linear(64.0 / 255.0)));
    EXPECT_EQ(t.texels32[4], float(srgb_to_linear(128.0 / 255.0)));
    EXPECT_EQ(t.texels32[7], 0.0f);  // alpha as stored
    // Row 1 is the file's top row.
    EXPECT_EQ(t.texels32[8], 1.0f);
    EXPECT_EQ(t.texels32[13], float(srgb_to_linear(128.0 / 255.0)));
    EXPECT_EQ(t.texels32[15], float(200.0 / 255.0));  // the exact fraction, correctly rounded
    // The IEC 61966-2-1 curve at a few points.
    EXPECT_DOUBLE_EQ(srgb_to_linear(0.04045), 0.04045 / 12.92);
    EXPECT_NEAR(srgb_to_linear(0.5), 0.214041, 1e-6);
    EXPECT_EQ(srgb_to_linear(std::nan("")), 0.0);
    EXPECT_EQ(srgb_to_linear(2.0), 1.0);
}

TEST_F(TextureFiles, LinearAsStoredKeepsEveryByte) {
    const Texture t = load({{"pattern", "file"},
                            {"file", "maps/rgba.png"},
                            {"format", "rgba8"},
                            {"colour_space", "linear"},
                            {"orientation", "as_stored"}});
    const std::vector<uint8_t> bytes = {255, 0, 0, 255, 0, 128, 0, 200, 0, 0, 64, 255, 128, 128, 128, 0};
    EXPECT_EQ(t.texels8, bytes);
}

TEST_F(TextureFiles, AFloatFileIsLinearAndKeepsItsRange) {
    const Texture t = load({{"pattern", "file"}, {"file", "maps/hdr.exr"}, {"orientation", "as_stored"}});
    const std::vector<float> texels = {4.5f, -1.0f, 0.25f, 1.0f, 100.0f, 0.5f, 0.0f, 0.5f};
    EXPECT_EQ(t.texels32, texels);
}

TEST_F(TextureFiles, GreyIsGreyInEveryColourChannel) {
    const fs::path grey = fs::absolute(SceneSources().find("conformance-file-grey16-r32f")->path).parent_path() /
                          "textures" / "grey-20x12.png";
    const Image image = read_image(grey.string());
    const Texture t = load({{"pattern", "file"}, {"file", grey.string()}, {"colour_space", "linear"}});
    ASSERT_EQ(t.width, 20);
    ASSERT_EQ(t.height, 12);
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 20; ++x) {
            // Upright (flipped), and the exact sixteen-bit fraction.
            const float g = float(std::nearbyint(double(image.rgba[(size_t(11 - y) * 20 + size_t(x)) * 4]) * 65535.0) / 65535.0);
            const float* texel = &t.texels32[(size_t(y) * 20 + size_t(x)) * 4];
            ASSERT_EQ(texel[0], g);
            ASSERT_EQ(texel[1], g);
            ASSERT_EQ(texel[2], g);
            ASSERT_EQ(texel[3], 1.0f);
        }
}

TEST_F(TextureFiles, ABoxChainIsGeneratedFromTheFile) {
    const Texture t = load({{"pattern", "file"}, {"file", "maps/wide.png"}, {"mipmaps", "box"}});
    ASSERT_EQ(t.level_count(), 3);  // 4x1, 2x1, 1x1
    EXPECT_EQ(t.mips[1].width, 1);
}

TEST_F(TextureFiles, ACubeReadsSixFacesAsStored) {
    nlohmann::json files = nlohmann::json::array();
    for (int i = 0; i < 6; ++i) files.push_back(i == 3 ? "maps/rgba.png" : "maps/small.png");
    const Texture t = load({{"pattern", "file"}, {"cube", true}, {"files", files}, {"colour_space", "linear"}});
    ASSERT_TRUE(t.cube);
    ASSERT_EQ(t.texels32.size(), 6u * 16u);
    EXPECT_EQ(t.texels32[3 * 16 + 0], 1.0f);          // face -y's first texel: the file's top-left
    EXPECT_EQ(t.texels32[0], 1.0f / 255.0f);          // +x's top-left, unflipped
}

TEST_F(TextureFiles, BadFilesAreRefusedNamingTheFieldAndTheFile) {
    const auto refused = [&](const nlohmann::json& texture, const std::string& words) {
        const std::string line = refusal(texture);
        EXPECT_NE(line.find(words), std::string::npos) << line;
        EXPECT_EQ(line.find('\n'), std::string::npos) << line;
    };
    refused({{"pattern", "file"}, {"file", "maps/none.png"}}, "field 'textures.0.file': cannot read " +
                                                                   (dir_ / "maps" / "none.png").string());
    refused({{"pattern", "file"}, {"file", "scene.json"}}, "field 'textures.0.file': cannot read");
    refused({{"pattern", "file"}}, "missing field 'textures.0.file'");
    refused({{"pattern", "file"}, {"cube", true}, {"file", "maps/rgba.png"}}, "field 'textures.0.file': a cube map reads six");
    refused({{"pattern", "file"}, {"files", nlohmann::json::array({"a", "b", "c", "d", "e", "f"})}},
            "field 'textures.0.files': six files make a cube map");
    refused({{"pattern", "file"}, {"cube", true}, {"files", nlohmann::json::array({"maps/rgba.png"})}},
            "field 'textures.0.files' must have 6 entries");
    nlohmann::json mixed = nlohmann::json::array();
    for (int i = 0; i < 6; ++i) mixed.push_back(i == 4 ? "maps/hdr.exr" : "maps/rgba.png");
    refused({{"pattern", "file"}, {"cube", true}, {"files", mixed}},
            "field 'textures.0.files.4' (" + (dir_ / "maps" / "hdr.exr").string() + "): 2x1, but the first face is 2x2");
    nlohmann::json oblong = nlohmann::json::array();
    for (int i = 0; i < 6; ++i) oblong.push_back("maps/hdr.exr");
    refused({{"pattern", "file"}, {"cube", true}, {"files", oblong}}, "a cube map's faces must be square (2x1)");
    refused({{"pattern", "file"}, {"file", "maps/rgba.png"}, {"mipmaps", "distinct"}},
            "field 'textures.0.mipmaps': `distinct` levels are generated patterns");
    refused({{"pattern", "file"}, {"file", "maps/rgba.png"}, {"width", 2}}, "unknown field 'textures.0.width'");
    refused({{"pattern", "noise"}, {"width", 2}, {"height", 2}, {"file", "maps/rgba.png"}},
            "unknown field 'textures.0.file'");
}

// The explorer's reproducers are written elsewhere: resolved paths are
// absolute, and an absolute path is kept.
TEST_F(TextureFiles, PathsAreResolvedAgainstTheScenesFolder) {
    nlohmann::json doc = read_builtin("conformance-file-cube-rgba8");
    doc["textures"][0]["files"][5] = "/abs/face.png";
    resolve_scene_paths(doc, "/scenes/here");
    EXPECT_EQ(doc["textures"][0]["files"][0], "/scenes/here/textures/cube-px.png");
    EXPECT_EQ(doc["textures"][0]["files"][5], "/abs/face.png");
    nlohmann::json untouched = doc;
    resolve_scene_paths(untouched, "");
    EXPECT_EQ(untouched, doc);
}

}  // namespace
}  // namespace st
