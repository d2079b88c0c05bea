// JPEG through libjpeg(-turbo): 8-bit sRGB codes, quality 98 (OpenImageIO's
// default, which kerf used before), grey or RGB (a fourth channel is not
// stored: JPEG has no alpha, and `kerf render --alpha` refuses .jpg).
// libjpeg's errors end the process by default; here they jump back and
// become the message.
#include <csetjmp>
#include <cstdio>
#include <cstdlib>

#include <jpeglib.h>

#include "render/image/codec_module/codecs.hpp"

namespace kerf::codec {

namespace {

struct ErrorJump {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX] = "";
};

void jump_back(j_common_ptr c) {
    auto* e = reinterpret_cast<ErrorJump*>(c->err);
    e->mgr.format_message(c, e->message);
    std::longjmp(e->jump, 1);
}

void no_output(j_common_ptr) {}

}  // namespace

// No C++ object with a destructor lives between setjmp and a longjmp.
std::string encode_jpeg(const std::uint8_t* pixels, int width, int height, int channels, Bytes& out) {
    if (channels < 1 || channels > 4 || channels == 2) return "JPEG: kerf writes 1, 3 or 4 channels";
    jpeg_compress_struct c{};
    ErrorJump err;
    c.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = jump_back;
    err.mgr.output_message = no_output;
    unsigned char* mem = nullptr;
    unsigned long size = 0;
    unsigned char* volatile row = nullptr;
    if (setjmp(err.jump)) {
        jpeg_destroy_compress(&c);
        std::free(mem);
        std::free(row);
        return std::string("JPEG: ") + err.message;
    }
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, &mem, &size);
    c.image_width = JDIMENSION(width);
    c.image_height = JDIMENSION(height);
    c.input_components = channels == 1 ? 1 : 3;
    c.in_color_space = channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 98, TRUE);
    jpeg_start_compress(&c, TRUE);
    row = static_cast<unsigned char*>(std::malloc(std::size_t(width) * 3));
    if (!row) err.mgr.error_exit(reinterpret_cast<j_common_ptr>(&c));
    while (c.next_scanline < c.image_height) {
        const std::uint8_t* in = pixels + std::size_t(c.next_scanline) * width * channels;
        JSAMPROW r = const_cast<JSAMPROW>(in);
        if (channels == 4) {  // drop alpha
            for (int x = 0; x < width; ++x)
                for (int k = 0; k < 3; ++k) row[x * 3 + k] = in[x * 4 + k];
            r = row;
        }
        jpeg_write_scanlines(&c, &r, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    std::free(row);
    out.assign(mem, mem + size);
    std::free(mem);
    return {};
}

std::string read_jpeg(const std::string& path, Pixels& out) {
    std::FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) return "cannot open the image";
    jpeg_decompress_struct d{};
    ErrorJump err;
    d.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = jump_back;
    err.mgr.output_message = no_output;
    float* volatile rgb = nullptr;
    unsigned char* volatile line = nullptr;
    if (setjmp(err.jump)) {
        jpeg_destroy_decompress(&d);
        std::fclose(f);
        std::free(rgb);
        std::free(line);
        return err.message;
    }
    jpeg_create_decompress(&d);
    jpeg_stdio_src(&d, f);
    jpeg_read_header(&d, TRUE);
    d.out_color_space = JCS_RGB;  // grey and CMYK/YCCK converted by libjpeg
    jpeg_start_decompress(&d);
    const int w = int(d.output_width), h = int(d.output_height);
    if (!sane_size(w, h) || d.output_components != 3) {
        std::snprintf(err.message, sizeof err.message, "image has no pixels or more than 2^28");
        std::longjmp(err.jump, 1);
    }
    rgb = static_cast<float*>(std::malloc(std::size_t(w) * h * 3 * sizeof(float)));
    line = static_cast<unsigned char*>(std::malloc(std::size_t(w) * 3));
    if (!rgb || !line) {
        std::snprintf(err.message, sizeof err.message, "out of memory");
        std::longjmp(err.jump, 1);
    }
    while (d.output_scanline < d.output_height) {
        float* o = rgb + std::size_t(d.output_scanline) * w * 3;
        JSAMPROW r = line;  // (volatile only for the jump)
        jpeg_read_scanlines(&d, &r, 1);
        for (int i = 0; i < w * 3; ++i) o[i] = line[i] * (1.0f / 255.0f);  // as OpenImageIO converts: the same floats
    }
    jpeg_finish_decompress(&d);
    jpeg_destroy_decompress(&d);
    std::fclose(f);
    out.width = w, out.height = h, out.encoded = true;
    out.rgb.assign(rgb, rgb + std::size_t(w) * h * 3);
    std::free(rgb);
    std::free(line);
    return {};
}

}  // namespace kerf::codec
