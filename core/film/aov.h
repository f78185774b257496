// Arbitrary output variables (AOVs): per-pixel images besides the beauty. The first-hit
// ones (albedo, normal, depth, position, object and material IDs, motion vectors) describe
// what the camera ray hit; variance and samples describe the beauty estimate itself.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/math/vec.h"

namespace penumbra {

enum class Aov : uint32_t {
    Albedo = 1,     // base colour at the first hit (working space)
    Normal = 2,     // world shading normal at the first hit, facing the camera
    Depth = 4,      // distance from the camera ray's origin to the first hit
    Position = 8,   // world position of the first hit
    Variance = 16,  // variance of the pixel's beauty estimate (of the mean), per channel
    Samples = 32,   // camera samples taken in the pixel
    // Relative standard error of the pixel's beauty, from two independently seeded halves
    // of its samples (core/film/error_estimate.h). Not a pure observer: asking for it
    // draws odd sample indices from a second sample stream, so it is not part of "all".
    Error = 64,
    // glTF node index and material index of the first surface a camera sample does not
    // pass through, from one sample per pixel (the one nearest the pixel's centre): IDs
    // are not averaged across objects. kNoHitId where none hit, kDefaultMaterialId for
    // a primitive without a material.
    ObjectId = 128,
    MaterialId = 256,
    // Cryptomatte (core/film/cryptomatte.h) of the same first surface's glTF node name
    // and material name: each pixel's IDs ranked by coverage, with anti-aliasing.
    CryptoObject = 512,
    CryptoMaterial = 1024,
    // Motion vectors, as Cycles' Vector pass: in raster pixels, Cycles' +Y up the image,
    // (previous - current, current - next) of the first surface's point, mapped by each
    // frame's camera (integrators/motion_vector.h). Averaged over the samples that hit,
    // as depth; 0 where none did.
    Vector = 2048,
    // Not an AOV of its own, and --aov does not name it (job/aov_list.h): the denoiser's input
    // (Film::denoise_input). The film keeps the guide features' sums and the beauty's
    // squares, over all samples and over the odd-indexed ones; like Error, it draws the
    // odd sample indices from a second sample stream.
    Denoise = 4096,
    // Not named either: a transparent background (--transparent-background). The film sums
    // each camera sample's coverage of geometry with the colour's weights, and its alpha
    // is their mean instead of 1.
    Coverage = 8192,
};

// The ID layers' values where no sample hit anything, and for glTF's default material.
constexpr int32_t kNoHitId = -1;
constexpr int32_t kDefaultMaterialId = -2;

class AovSet {
public:
    AovSet() = default;
    AovSet(std::initializer_list<Aov> aovs) {
        for (Aov a : aovs) add(a);
    }
    void add(Aov a) { m_bits |= uint32_t(a); }
    bool has(Aov a) const { return (m_bits & uint32_t(a)) != 0; }
    bool any() const { return m_bits != 0; }
    // Albedo, normal, depth or position: the render loop must find the first hit.
    bool needs_first_hit() const {
        return (m_bits & (uint32_t(Aov::Albedo) | uint32_t(Aov::Normal) | uint32_t(Aov::Depth) |
                          uint32_t(Aov::Position) | uint32_t(Aov::ObjectId) |
                          uint32_t(Aov::MaterialId) | uint32_t(Aov::CryptoObject) |
                          uint32_t(Aov::CryptoMaterial) | uint32_t(Aov::Vector))) != 0;
    }
    bool has_ids() const { return has(Aov::ObjectId) || has(Aov::MaterialId); }
    // Error or denoising: the samples form two independently seeded halves.
    bool splits_halves() const { return has(Aov::Error) || has(Aov::Denoise); }

private:
    uint32_t m_bits = 0;
};

// The denoiser's guide features of one camera sample (core/denoise/denoise_input.h): the
// first non-specular surface's albedo, tinted by the specular surfaces on the way, its
// shading normal facing the incoming ray, the length of the path to it, and whether a
// light sample from it is unoccluded (its transmittance). A sample that escapes leaves
// all four zero.
struct GuideRecord {
    Spectrum albedo;
    Vec3 normal;
    float depth = 0;
    float visibility = 0;
};

// What one camera sample saw first. Misses leave hit false; the film then counts them
// as zero albedo and normal and leaves them out of depth and position.
struct AovRecord {
    bool hit = false;
    Spectrum albedo;
    Vec3 normal;
    Vec3 position;
    float depth = 0;
    // The first surface's glTF node and material (Aov::ObjectId, Aov::MaterialId), and
    // the Cryptomatte hashes of their names (read where hit).
    int32_t object = kNoHitId, material = kNoHitId;
    uint32_t object_hash = 0, material_hash = 0;
    // The first surface's motion vector (Aov::Vector), read where hit.
    Vec4 motion;
    // Squared distance of the sample from the pixel's centre, in pixels: the ID layers
    // keep the nearest sample's IDs.
    float offset2 = 0;
    // The camera ray's coverage of geometry (Aov::Coverage): 1 minus the share of it that
    // passes every surface and escapes (integrators/camera_coverage.h).
    float coverage = 1;
    // The sample's index is odd: it belongs to the second half of the error estimate.
    bool odd = false;
    GuideRecord guide;  // only read by a film that denoises
};

}  // namespace penumbra
