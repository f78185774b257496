// RGB colour spaces by their primaries and white point (CIE 1931 xy): the matrix to
// CIE XYZ, Bradford white adaptation, and the reverse, recognising a space from its
// matrix, which is how an OCIO colour space gets its EXR `chromaticities`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/math/mat3.h"

namespace penumbra {

// The layout of OpenEXR's `chromaticities` attribute (and OIIO's 8 floats).
struct Chromaticities {
    float red[2], green[2], blue[2], white[2];
};

struct NamedPrimaries {
    std::string name;
    Chromaticities xy;
};

// Rec.709 / sRGB primaries with D65: glTF's colour space.
const Chromaticities& rec709_chromaticities();
// ACES AP1 (ACEScg) and AP0 (ACES2065-1), both with the ACES white (~D60).
const Chromaticities& ap1_chromaticities();
const Chromaticities& ap0_chromaticities();
// Rec.709, ACEScg (AP1), ACES2065-1 (AP0), Rec.2020, Display P3 (D65).
const std::vector<NamedPrimaries>& known_primaries();

// The normalised primary matrix: linear RGB in the space to XYZ (Y of white = 1).
Mat3 rgb_to_xyz(const Chromaticities& c);
// Bradford chromatic adaptation from one white (xy) to another.
Mat3 bradford(const float from_white[2], const float to_white[2]);
// RGB to XYZ seen under D65: rgb_to_xyz followed by Bradford adaptation to D65. This is
// what OCIO's "..._to_CIE-XYZ-D65_BFD" builtins compute, and what a config's XYZ-D65
// interchange space exposes.
Mat3 rgb_to_xyz_d65(const Chromaticities& c);

// The chromaticities of a linear space from its matrix to XYZ-D65. A known space
// (known_primaries) matching within `tolerance` gives its exact published values,
// native white included (adaptation hides the white of AP0/AP1 otherwise). Any other
// space is read off the matrix's columns, white = M (1,1,1): exact for D65 spaces.
// Empty when the matrix is singular or its columns have no chromaticity (sum <= 0).
std::optional<Chromaticities> chromaticities_from_xyz_d65(const Mat3& to_xyz_d65,
                                                          double tolerance = 2e-3);

}  // namespace penumbra
