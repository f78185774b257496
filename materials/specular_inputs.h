// The glTF inputs of the specular lobe at a hit (KHR_materials_anisotropy and
// KHR_materials_iridescence): factors times textures, and the shading frame turned to the
// anisotropy direction. Called from shade() (materials/material.cpp).
#pragma once

#include "core/math/frame.h"
#include "core/scene/scene.h"
#include "core/surface_point.h"
#include "materials/metal_rough_bsdf.h"

namespace penumbra {

// KHR_materials_anisotropy: turns frame (z = the shading normal, on the viewer's side)
// about its normal so that x follows the anisotropy direction: the tangent (the vertex
// TANGENT, else dp/du, made orthogonal to the normal) rotated by anisotropyRotation and by
// the texture's RG direction. Returns the strength, anisotropyStrength x texture B, in
// [0, 1]; 0 (also where the mesh gives no tangent) leaves the frame as it is.
float align_anisotropy_frame(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp,
                             Frame& frame);

// KHR_materials_iridescence: sets p.iridescence (iridescenceFactor x texture R) and
// p.film (IOR, and thickness mix(min, max, texture G) nm, max without a texture).
void set_iridescence(const Scene& scene, const MaterialDesc& m, const SurfacePoint& sp,
                     MetalRoughParams& p);

}  // namespace penumbra
