// image_io.cpp: OpenImageIO readers and writers, with temp-and-rename.
#include "image/image_io.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include "image/file_provenance.h"
#include "image/png_structure.h"
#include "image/stderr_capture.h"
#include "image/unorm8.h"

namespace st {

namespace fs = std::filesystem;

namespace {

// A temporary name in the target's folder (rename stays on one filesystem);
// the extension is kept so OpenImageIO picks the right format.
std::string temp_name(const std::string& path) {
    fs::path p(path);
    return (p.parent_path() / (".tmp-" + std::to_string(getpid()) + "-" + p.filename().string()))
        .string();
}

void commit(const std::string& tmp, const std::string& path) {
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write " + path + ": rename failed");
    }
}

void write_with_oiio(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                     const void* data) {
    const std::string tmp = temp_name(path);
    auto out = OIIO::ImageOutput::create(tmp);
    if (!out) throw std::runtime_error("cannot write " + path + ": " + OIIO::geterror());
    bool ok = out->open(tmp, spec) && out->write_image(type, data);
    ok = out->close() && ok;
    if (!ok) {
        std::string err = out->geterror();
        std::error_code ec;
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write " + path + ": " + err);
    }
    commit(tmp, path);
}

}  // namespace

void write_exr(const std::string& path, const Image& image, const Metadata& metadata) {
    OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
    spec.attribute("compression", "zip");
    for (const auto& [key, value] : file_provenance().attributes) spec.attribute("shadertwin:" + key, value);
    for (const auto& [key, value] : metadata) spec.attribute("shadertwin:" + key, value);
    write_with_oiio(path, spec, OIIO::TypeDesc::FLOAT, image.rgba.data());
}

void write_png(const std::string& path, const Image& image) {
    std::vector<unsigned char> bytes(image.rgba.size());
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = to_unorm8(image.rgba[i]);
    write_png_bytes(path, image.width, image.height, 4, bytes.data());
}

void write_png_bytes(const std::string& path, int width, int height, int channels,
                     const unsigned char* bytes) {
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
    for (const auto& [key, value] : file_provenance().attributes) spec.attribute("shadertwin:" + key, value);
    write_with_oiio(path, spec, OIIO::TypeDesc::UINT8, bytes);
}

Image read_image(const std::string& path, Metadata* metadata) {
    // libpng prints its errors itself before OpenImageIO reports them: hold
    // that back, so that a refused image gets one line, and ours.
    StderrCapture library_chatter;
    auto refuse = [&](const std::string& why) {
        std::string line = join_lines(why);
        if (line.empty()) line = join_lines(library_chatter.text());
        if (line.empty()) line = "not an image OpenImageIO reads";
        return std::runtime_error("cannot read " + path + ": " + line);
    };
    if (const std::string broken = png_structure_error(path); !broken.empty()) throw refuse(broken);
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw refuse(OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.nchannels < 1) throw std::runtime_error("cannot read " + path + ": no channels");
    // The header's size is checked before anything is allocated for it: a
    // corrupt or hostile header may claim gigabytes.
    if (spec.width < 1 || spec.height < 1 || spec.width > kMaxImageSide || spec.height > kMaxImageSide ||
        spec.nchannels > 64 || spec.depth > 1)
        throw std::runtime_error("cannot read " + path + ": its header says " + std::to_string(spec.width) + "x" +
                                 std::to_string(spec.height) + "x" + std::to_string(spec.depth) + " with " +
                                 std::to_string(spec.nchannels) + " channels; images up to " +
                                 std::to_string(kMaxImageSide) + " pixels a side and 64 channels are read");
    Image image(spec.width, spec.height);
    std::vector<float> raw(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, raw.data())) throw refuse(in->geterror());
    for (size_t p = 0; p < size_t(spec.width) * spec.height; ++p)
        for (int c = 0; c < 4; ++c)
            image.rgba[p * 4 + c] = c < spec.nchannels ? raw[p * spec.nchannels + c]
                                                       : (c == 3 ? 1.0f : 0.0f);
    if (metadata) {
        for (const auto& attr : spec.extra_attribs) {
            std::string name = attr.name().string();
            if (name.rfind("shadertwin:", 0) == 0) (*metadata)[name.substr(11)] = attr.get_string();
        }
    }
    in->close();
    return image;
}

namespace {

void write_whole(const std::string& path, const std::string& text) {
    const std::string tmp = temp_name(path);
    {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush()) {
            std::error_code ec;
            fs::remove(tmp, ec);
            throw std::runtime_error("cannot write " + path);
        }
    }
    commit(tmp, path);
}

}  // namespace

void write_text_file(const std::string& path, const std::string& text) {
    write_whole(path, with_provenance(path, text, file_provenance().line));
}

void write_copied_text_file(const std::string& path, const std::string& text) {
    write_whole(path, with_provenance(path, text, file_provenance().line, "copied by"));
}

}  // namespace st
