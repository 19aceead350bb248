// png_file.cpp: see png_file.h.
#include "image/png_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

#include <png.h>

namespace st {

namespace {

struct PngErrors {
    char message[256] = "";
};

void on_error(png_structp png, png_const_charp message) {
    auto* e = static_cast<PngErrors*>(png_get_error_ptr(png));
    std::snprintf(e->message, sizeof e->message, "%s", message);
    // Returning makes libpng longjmp to the setjmp in write_rows.
}

void on_warning(png_structp, png_const_charp) {}  // nothing on stderr

// Only C objects live here past setjmp: libpng's longjmp skips no destructor.
bool write_rows(FILE* file, png_structp png, png_infop info, int width, int height, int colour_type,
                png_text* texts, int text_count, png_bytep* rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_set_compression_level(png, 1);
    png_set_IHDR(png, info, png_uint_32(width), png_uint_32(height), 8, colour_type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (text_count > 0) png_set_text(png, info, texts, text_count);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    return true;
}

}  // namespace

std::string write_png_file(const std::string& path, int width, int height, int channels, const uint8_t* pixels,
                           const std::map<std::string, std::string>& attributes) {
    static constexpr int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                           PNG_COLOR_TYPE_RGB_ALPHA};
    if (width < 1 || height < 1 || channels < 1 || channels > 4) return "no PNG of that shape";
    // Every C++ object first: nothing with a destructor is made after setjmp.
    std::vector<std::string> keys, values;
    for (const auto& [key, value] : attributes) {
        if (key.empty() || key.size() > 79) return "attribute name '" + key + "' is no PNG keyword";
        keys.push_back(key);
        values.push_back(value);
    }
    std::vector<png_text> texts(keys.size());
    for (size_t i = 0; i < keys.size(); ++i) {
        texts[i].compression = PNG_TEXT_COMPRESSION_NONE;
        texts[i].key = keys[i].data();
        texts[i].text = values[i].data();
        texts[i].text_length = values[i].size();
    }
    const size_t stride = size_t(width) * size_t(channels);
    std::vector<png_bytep> rows(static_cast<size_t>(height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = const_cast<png_bytep>(pixels + y * stride);
    PngErrors errors;

    FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return std::strerror(errno);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_error, on_warning);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    bool ok = info && write_rows(file, png, info, width, height, kColourTypes[channels - 1], texts.data(),
                                 int(texts.size()), rows.data());
    png_destroy_write_struct(png ? &png : nullptr, info ? &info : nullptr);
    const bool closed = std::fclose(file) == 0;
    if (!ok) return errors.message[0] ? errors.message : "libpng could not start";
    if (!closed) return std::strerror(errno);
    return {};
}

}  // namespace st
