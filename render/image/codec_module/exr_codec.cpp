// EXR through OpenEXR: 32-bit float channels (Y; R, G, B; R, G, B, A),
// ZIP compression (OpenImageIO's default, which kerf used before), encoded
// into a memory stream.
#include <cstring>
#include <exception>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>

#include "render/image/codec_module/codecs.hpp"

namespace kerf::codec {

namespace {

// OpenEXR writes through an OStream; this one appends to (and seeks in) bytes.
class MemoryStream : public Imf::OStream {
public:
    explicit MemoryStream(Bytes& bytes) : Imf::OStream("memory"), bytes_(bytes) {}
    void write(const char c[], int n) override {
        if (pos_ + std::size_t(n) > bytes_.size()) bytes_.resize(pos_ + std::size_t(n));
        std::memcpy(bytes_.data() + pos_, c, std::size_t(n));
        pos_ += std::size_t(n);
    }
    uint64_t tellp() override { return pos_; }
    void seekp(uint64_t pos) override { pos_ = std::size_t(pos); }

private:
    Bytes& bytes_;
    std::size_t pos_ = 0;
};

const char* channel_name(int channels, int c) {
    static const char* const rgba[] = {"R", "G", "B", "A"};
    return channels == 1 ? "Y" : rgba[c];
}

}  // namespace

std::string encode_exr(const float* pixels, int width, int height, int channels, Bytes& out) {
    if (channels != 1 && channels != 3 && channels != 4) return "EXR: kerf writes 1, 3 or 4 channels";
    try {
        Imf::Header header(width, height);
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frame;
        const std::size_t xs = sizeof(float) * std::size_t(channels), ys = xs * std::size_t(width);
        for (int c = 0; c < channels; ++c) {
            header.channels().insert(channel_name(channels, c), Imf::Channel(Imf::FLOAT));
            frame.insert(channel_name(channels, c),
                         Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(pixels + c)), xs, ys));
        }
        out.clear();
        MemoryStream stream(out);
        Imf::OutputFile file(stream, header);
        file.setFrameBuffer(frame);
        file.writePixels(height);
    } catch (const std::exception& e) {
        return std::string("EXR: ") + e.what();
    }
    return {};
}

std::string read_exr(const std::string& path, Pixels& out) {
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i dw = file.header().dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        if (!sane_size(w, h)) return "image has no pixels or more than 2^28";
        const Imf::ChannelList& list = file.header().channels();
        const bool rgb = list.findChannel("R") && list.findChannel("G") && list.findChannel("B");
        const char* grey = list.findChannel("Y") ? "Y" : nullptr;
        if (!grey && !rgb && list.begin() != list.end()) grey = list.begin().name();  // one named otherwise
        if (!rgb && !grey) return "EXR without R, G, B or Y channels";
        std::vector<float> all(std::size_t(w) * h * 3);
        Imf::FrameBuffer frame;
        // The slices' base is shifted so that the data window's corner lands on all[0].
        char* base = reinterpret_cast<char*>(all.data()) -
                     (std::ptrdiff_t(dw.min.x) + std::ptrdiff_t(dw.min.y) * w) * std::ptrdiff_t(3 * sizeof(float));
        const std::size_t xs = 3 * sizeof(float), ys = xs * std::size_t(w);
        for (int c = 0; c < (rgb ? 3 : 1); ++c)  // a frame buffer holds each name once: grey is copied after
            frame.insert(rgb ? channel_name(3, c) : grey, Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xs, ys));
        file.setFrameBuffer(frame);
        file.readPixels(dw.min.y, dw.max.y);
        if (!rgb)
            for (std::size_t i = 0; i < all.size(); i += 3) all[i + 1] = all[i + 2] = all[i];
        out.width = w, out.height = h, out.encoded = false;
        out.rgb = std::move(all);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

}  // namespace kerf::codec
