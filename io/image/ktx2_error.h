// The one exception the KTX2 and Basis Universal decoders throw: what is wrong with the
// bytes, without the image's name (ktx2_decoder.cpp adds it as an ImageDecodeError).
#pragma once

#include <stdexcept>

namespace penumbra {

class Ktx2Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace penumbra
