// How KHR_lights_punctual intensities are read: as the photometric units the spec names
// (candela, lux), converted to radiometric ones at 683 lm/W, or as radiometric numbers.
#pragma once

#include <stdexcept>
#include <string>

namespace penumbra {

enum class LightUnits {
    Photometric,  // cd -> W/sr and lux -> W/m^2, divided by 683 lm/W (glTF's units)
    Radiometric,  // the number is already W/sr or W/m^2
};

// The luminous efficacy at 555 nm, which defines the candela (SI, 1979) and which
// Blender's glTF add-on uses both ways (PBR_WATTS_TO_LUMENS in its conversion module).
constexpr double kLumensPerWatt = 683.0;

// The factor from a file's intensity to radiant intensity (W/sr) or irradiance (W/m^2).
// Applied in double so that intensities written as 683 x a round number read back exact.
inline double radiometric_scale(LightUnits units) {
    return units == LightUnits::Photometric ? 1.0 / kLumensPerWatt : 1.0;
}

}  // namespace penumbra
