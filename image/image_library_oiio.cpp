// image_library_oiio.cpp: the ImageLibrary on OpenImageIO (see
// image_library.h), built as libshadertwin_oiio.so. The only file that
// includes OpenImageIO.
#include "image/image_library.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

namespace st {
namespace {

class OiioLibrary final : public ImageLibrary {
public:
    bool read(const std::string& path, int max_side, int& width, int& height, std::vector<float>& rgba,
              std::map<std::string, std::string>& attributes, std::string& error) const override {
        // The values as stored: OpenImageIO would multiply a PNG's colour
        // by its alpha on reading (associated alpha), which a texture
        // uploaded as stored, or a diff of two files, must not see.
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        auto in = OIIO::ImageInput::open(path, &config);
        if (!in) {
            error = OIIO::geterror();
            return false;
        }
        const OIIO::ImageSpec& spec = in->spec();
        if (spec.nchannels < 1) {
            error = "no channels";
            return false;
        }
        // The header's size is checked before anything is allocated for it:
        // a corrupt or hostile header may claim gigabytes.
        if (spec.width < 1 || spec.height < 1 || spec.width > max_side || spec.height > max_side ||
            spec.nchannels > 64 || spec.depth > 1) {
            error = "its header says " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + "x" +
                    std::to_string(spec.depth) + " with " + std::to_string(spec.nchannels) + " channels; images up to " +
                    std::to_string(max_side) + " pixels a side and 64 channels are read";
            return false;
        }
        width = spec.width;
        height = spec.height;
        const size_t pixels = size_t(spec.width) * size_t(spec.height);
        std::vector<float> raw(pixels * size_t(spec.nchannels));
        if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, raw.data())) {
            error = in->geterror();
            return false;
        }
        rgba.assign(pixels * 4, 0.0f);
        for (size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < 4; ++c)
                rgba[p * 4 + size_t(c)] = c < spec.nchannels ? raw[p * size_t(spec.nchannels) + size_t(c)]
                                                             : (c == 3 ? 1.0f : 0.0f);
        for (const auto& attr : spec.extra_attribs) {
            const std::string name = attr.name().string();
            if (name.rfind("shadertwin:", 0) == 0) attributes[name] = attr.get_string();
        }
        // What the file holds, for a reader that decodes it (a texture's
        // colour space): "file:" is not a prefix any file attribute has.
        attributes["file:pixel_type"] = spec.format.c_str();
        attributes["file:channels"] = std::to_string(spec.nchannels);
        attributes["file:colour_space"] = spec.get_string_attribute("oiio:ColorSpace");
        in->close();
        return true;
    }

    std::string pixel_hash(const float* rgba, int width, int height) const override {
        OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
        // Wrapped without copying; rows are already top to bottom.
        OIIO::ImageBuf buf(spec, const_cast<float*>(rgba));
        return OIIO::ImageBufAlgo::computePixelHashSHA1(buf);
    }

    ImageErrorStats error_stats(const float* a, const float* b, int width, int height) const override {
        OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
        OIIO::ImageBuf ba(spec, const_cast<float*>(a));
        OIIO::ImageBuf bb(spec, const_cast<float*>(b));
        const auto r = OIIO::ImageBufAlgo::compare(ba, bb, 0.0f, 0.0f);
        return {r.maxerror, r.meanerror, r.rms_error, r.PSNR};
    }
};

}  // namespace
}  // namespace st

extern "C" __attribute__((visibility("default"))) const st::ImageLibrary* shadertwin_image_library(int version) {
    static const st::OiioLibrary library;
    return version == st::kImageLibraryVersion ? &library : nullptr;
}
