// exr_file.cpp: see exr_file.h.
#include "image/exr_file.h"

#include <exception>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

namespace st {

std::string write_exr_file(const std::string& path, int width, int height, const float* rgba,
                           const std::map<std::string, std::string>& attributes) {
    if (width < 1 || height < 1) return "no EXR of that shape";
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        static constexpr const char* kChannels[] = {"R", "G", "B", "A"};
        for (const char* c : kChannels) header.channels().insert(c, Imf::Channel(Imf::FLOAT));
        for (const auto& [key, value] : attributes) header.insert(key, Imf::StringAttribute(value));
        Imf::FrameBuffer frame;
        const size_t pixel = 4 * sizeof(float), row = pixel * size_t(width);
        for (int c = 0; c < 4; ++c)
            frame.insert(kChannels[c], Imf::Slice(Imf::FLOAT, (char*)(rgba + c), pixel, row));
        Imf::OutputFile file(path.c_str(), header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace st
