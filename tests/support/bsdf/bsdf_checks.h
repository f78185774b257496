// Statistical checks shared by the BSDF tests: chi-square of sample() against pdf(), and
// the directional albedo (the white furnace) as a Monte Carlo estimate with its error.
#pragma once

#include "materials/bsdf.h"
#include "support/statistics/chi2.h"

namespace penumbra::test {

struct BsdfChi2Options {
    int samples = 200000;
    uint64_t seed = 1;
    double significance = 0.01;  // already Sidak-corrected for the suite
    // Specular samples carry a lobe probability, not a density: by default they count
    // as "no sample", so pdf() must integrate to 1 - P(specular).
    bool keep_specular = false;
    // Bin wi over the whole sphere (models that transmit) instead of the upper hemisphere.
    bool full_sphere = false;
    int cos_bins = 10;
};

// Over the upper hemisphere a sample below the horizon fails the test.
Chi2Result bsdf_chi2(const Bsdf& bsdf, Vec3 wo, const BsdfChi2Options& options,
                     Transport mode = Transport::Radiance);

struct AlbedoEstimate {
    Spectrum mean;       // of f |cos| / pdf, failed samples counting as 0
    Spectrum std_error;  // of the mean
};
AlbedoEstimate directional_albedo(const Bsdf& bsdf, Vec3 wo, int samples, uint64_t seed,
                                  Transport mode = Transport::Radiance);

// A unit direction at cos(theta) = cos_theta and azimuth phi.
Vec3 spherical_direction(float cos_theta, float phi);

}  // namespace penumbra::test
