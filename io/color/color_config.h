// Internal to io/: the OpenColorIO config penumbra uses when neither --ocio-config nor
// $OCIO names one, built in code from OCIO 2.1's builtin transforms so that it needs no
// files (and cannot go missing from an installation).
#pragma once

#include <OpenColorIO/OpenColorIO.h>

namespace penumbra {

namespace OCIO = OCIO_NAMESPACE;

// Names of the built-in config's colour spaces and displays (see docs/conventions.md).
inline constexpr const char* kLinearRec709 = "Linear Rec.709 (sRGB)";
inline constexpr const char* kAcescg = "ACEScg";
inline constexpr const char* kAces2065 = "ACES2065-1";
inline constexpr const char* kSrgbEncoded = "sRGB";
inline constexpr const char* kSrgbDisplay = "sRGB";

// Reference space: linear Rec.709 (glTF's); display reference: CIE XYZ D65. Validated.
OCIO::ConstConfigRcPtr builtin_config();

}  // namespace penumbra
