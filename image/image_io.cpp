// image_io.cpp: image readers (OpenImageIO, through image_library.h) and
// writers (libpng and OpenEXR: png_file.h, exr_file.h), with
// temp-and-rename.
#include "image/image_io.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include <unistd.h>

#include "image/exr_file.h"
#include "image/file_provenance.h"
#include "image/image_library.h"
#include "image/png_file.h"
#include "image/png_structure.h"
#include "image/stderr_capture.h"
#include "image/unorm8.h"

namespace st {

namespace fs = std::filesystem;

namespace {

// A temporary name in the target's folder (rename stays on one filesystem);
// the extension is kept, so a half-written file shows its kind.
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

// Writes through `write` (a png_file.h or exr_file.h writer given the
// temporary name) and renames the result into place.
template <class Writer>
void write_then_commit(const std::string& path, Writer&& write) {
    const std::string tmp = temp_name(path);
    const std::string err = write(tmp);
    if (!err.empty()) {
        std::error_code ec;
        fs::remove(tmp, ec);
        throw std::runtime_error("cannot write " + path + ": " + err);
    }
    commit(tmp, path);
}

std::map<std::string, std::string> provenance_attributes() {
    std::map<std::string, std::string> out;
    for (const auto& [key, value] : file_provenance().attributes) out["shadertwin:" + key] = value;
    return out;
}

}  // namespace

void write_exr(const std::string& path, const Image& image, const Metadata& metadata) {
    std::map<std::string, std::string> attributes = provenance_attributes();
    for (const auto& [key, value] : metadata) attributes["shadertwin:" + key] = value;
    write_then_commit(path, [&](const std::string& tmp) {
        return write_exr_file(tmp, image.width, image.height, image.rgba.data(), attributes);
    });
}

void write_png(const std::string& path, const Image& image) {
    std::vector<unsigned char> bytes(image.rgba.size());
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = to_unorm8(image.rgba[i]);
    write_png_bytes(path, image.width, image.height, 4, bytes.data());
}

void write_png_bytes(const std::string& path, int width, int height, int channels,
                     const unsigned char* bytes) {
    write_then_commit(path, [&](const std::string& tmp) {
        return write_png_file(tmp, width, height, channels, bytes, provenance_attributes());
    });
}

Image read_image(const std::string& path, Metadata* metadata, ImageFileFormat* format) {
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
    Image image;
    std::map<std::string, std::string> attributes;
    std::string error;
    if (!image_library().read(path, kMaxImageSide, image.width, image.height, image.rgba, attributes, error))
        throw refuse(error);
    const std::string ours = "shadertwin:";
    if (metadata)
        for (const auto& [name, value] : attributes)
            if (name.rfind(ours, 0) == 0) (*metadata)[name.substr(ours.size())] = value;
    if (format) {
        format->pixel_type = attributes["file:pixel_type"];
        format->channels = std::atoi(attributes["file:channels"].c_str());
        format->colour_space = attributes["file:colour_space"];
    }
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
