#include "support/exr_pixels.h"

#include <OpenImageIO/imageio.h>

#include <cstring>
#include <memory>

namespace penumbra::test {

Pixels read_pixels(const std::string& path) {
    Pixels p;
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path);
    if (!in) {
        p.error = "cannot open " + path;
        return p;
    }
    const OIIO::ImageSpec& s = in->spec();
    p.width = s.width;
    p.height = s.height;
    p.channels = s.channelnames;
    p.data.resize(size_t(s.width) * s.height * s.nchannels);
    if (!in->read_image(0, 0, 0, s.nchannels, OIIO::TypeDesc::FLOAT, p.data.data()))
        p.error = in->geterror();
    return p;
}

::testing::AssertionResult same_pixels(const std::string& a, const std::string& b) {
    const Pixels pa = read_pixels(a), pb = read_pixels(b);
    if (!pa.error.empty() || !pb.error.empty())
        return ::testing::AssertionFailure() << pa.error << " " << pb.error;
    if (pa.width != pb.width || pa.height != pb.height || pa.channels != pb.channels)
        return ::testing::AssertionFailure() << a << " and " << b << " differ in size or channels";
    const size_t nc = pa.channels.size();
    size_t differing = 0, first = 0;
    for (size_t px = 0; px < size_t(pa.width) * pa.height; ++px)
        if (std::memcmp(&pa.data[px * nc], &pb.data[px * nc], nc * sizeof(float)) != 0)
            if (differing++ == 0) first = px;
    if (differing == 0) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << a << " and " << b << " differ in " << differing << " pixels, the first at ("
           << first % pa.width << ", " << first / pa.width << ")";
}

}  // namespace penumbra::test
