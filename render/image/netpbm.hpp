// The two Netpbm formats whose names promise a content (docs/spec.md §7):
// `.pgm` is grey, so a colour image is reduced to its luminance; `.pfm` is
// linear floats, which OpenImageIO reads but does not write, so kerf
// encodes it (a header and raw rows: nothing a library would add).
#pragma once
#include <vector>

#include "render/image/image.hpp"

namespace kerf::render {

// The image's luminance (Rec. 709 weights on linear light) as a one-channel
// image of the same kind of storage (linear floats, or sRGB bytes decoded,
// weighted and encoded again). Images of one channel are returned as is.
Image grey_image(const Image& colour);

// A PFM file of `image` (1 or 3 channels of floats): "Pf"/"PF", size,
// -1 (little-endian), then rows from the bottom up as the format says.
std::vector<unsigned char> encode_pfm(const Image& image);

}  // namespace kerf::render
