// Light from infinitely far away: a constant colour or an equirectangular (lat-long)
// image, importance-sampled with a 2D piecewise-constant distribution over the image
// weighted by sin(theta) (PBRT's infinite area light).
//
// Mapping (glTF +Y up): theta = acos(y) from +Y, phi = atan2(-z, -x); the image's u =
// phi / 2pi + 1/2 and v = theta / pi, which matches Blender's equirectangular
// convention after its Z-up to glTF's Y-up conversion. `rotation` turns the map about +Y.
#pragma once

#include "core/image.h"
#include "core/lights/light.h"
#include "core/sampling/distribution.h"

namespace penumbra {

// Which distribution an image environment's light samples follow. Full: the image's
// luminance. MisCompensated (Karlik et al. 2019, "MIS Compensation"; pbrt-v4's
// allowIncompletePDF): luminance less its mean over the sphere, clamped at 0, so that no
// light sample goes to texels dimmer than the mean. BSDF sampling finds those as well
// as light sampling did, and MIS then gives it their whole weight: with the sun-lit sky
// of the efficiency harness, FlightHelmet's relMSE falls to 0.66x at equal samples
// (docs/performance.md). Only for integrators whose every light sample is MIS-weighted
// against a BSDF sample (Integrator::pairs_light_and_bsdf_samples): a light sample
// alone would never see those texels. A map that is constant gives no compensated
// distribution and keeps the full one.
enum class EnvironmentSampling { Full, MisCompensated };

class EnvironmentLight;
// "full" or "compensated" as the light samples (a constant environment's are uniform:
// "full"), "none" for no environment: the EXR header's penumbra:env_sampling.
const char* environment_sampling_name(const EnvironmentLight* env);

class EnvironmentLight final : public Light {
public:
    // Constant radiance in every direction.
    EnvironmentLight(Spectrum radiance, float scene_radius);
    // Equirectangular image (linear RGB), scaled by intensity, rotated by degrees about +Y.
    EnvironmentLight(Image image, float intensity, float rotation_degrees, float scene_radius,
                     EnvironmentSampling sampling = EnvironmentSampling::Full);

    std::optional<LightSample> sample_Li(const ShadingPoint& ref, Vec2 u,
                                         float time) const override;
    float pdf_Li(const ShadingPoint& ref, Vec3 wi, float time) const override;
    float power() const override;
    bool is_delta() const override { return false; }
    std::string describe() const override { return "environment"; }
    // Radiance arriving from direction w (unit, world), i.e. seen looking along w.
    Spectrum Le(Vec3 w) const;
    // Le(w) and pdf_Li's density for w from one mapping of w to the image: a BSDF-sampled
    // ray that escapes needs both, and the mapping (two atan2) is most of either.
    Spectrum Le(Vec3 w, float* pdf) const;

    // MisCompensated only where it was asked for and the map is not constant.
    EnvironmentSampling sampling() const { return m_sampling; }

    Vec2 direction_to_uv(Vec3 w) const;
    Vec3 uv_to_direction(Vec2 uv) const;

private:
    // Le and pdf_Li at the image coordinates of a direction (image maps only).
    Spectrum texel_radiance(Vec2 uv) const;
    float uv_pdf(Vec2 uv) const;

    Spectrum m_constant;
    Image m_image;
    // The image's RGB times the intensity, the values Le returns, packed: Le reads 12
    // bytes instead of going through Image::rgba's switch on the channel count.
    std::vector<Spectrum> m_radiance;
    float m_scale = 1;
    float m_cos_rot = 1, m_sin_rot = 0;
    float m_radius;
    Distribution2D m_dist;  // what sample_Li and pdf_Li follow
    // The full distribution's integral (mean luminance times sin(theta)): the light's
    // power, which the light set chooses lights by, whichever distribution samples it.
    float m_luminance_integral = 0;
    EnvironmentSampling m_sampling = EnvironmentSampling::Full;
};

}  // namespace penumbra
