// Cryptomatte IDs (Friedman and Jones 2015, specification 1.2): names hashed with
// MurmurHash3_x86_32 (seed 0), each hash stored as the float with its bits, nudged off the
// exponents of denormals, infinities and NaNs so that no reader's arithmetic changes it.
// A pixel keeps the coverage of the few IDs its samples found, ranked at write time.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/scene/scene.h"

namespace penumbra {

// MurmurHash3_x86_32 of name with seed 0, as the specification and Blender compute it.
uint32_t cryptomatte_hash(std::string_view name);
// The hash as the float an ID channel stores: its bits, with bit 23 flipped where the
// exponent would be 0 or 255.
float cryptomatte_float(uint32_t hash);
// The header's manifest: {"name":"hex hash",...} in the order given (names repeated keep
// their first place).
std::string cryptomatte_manifest(const std::vector<std::string>& names);
// The header key of a Cryptomatte layer's entry ("name", "hash", "conversion", "manifest"):
// "cryptomatte/" plus the first 7 hex digits of the layer name's hash, then "/" entry.
std::string cryptomatte_key(const std::string& layer, const std::string& entry);

// The names the two layers hash: an instance's glTF node name (its "nodes[i]" path where
// the node has none, and for EXT_mesh_gpu_instancing's copies) and a material's name
// ("default" for glTF's default material).
std::string cryptomatte_object_name(const Scene& scene, uint32_t instance);
const std::string& cryptomatte_material_name(const Scene& scene, int material);
// Every name of one layer in the scene, for its manifest.
std::vector<std::string> cryptomatte_object_names(const Scene& scene);
std::vector<std::string> cryptomatte_material_names(const Scene& scene);

// Every instance's and material's hash, computed once per render rather than per sample:
// objects[instance], materials[material], and the default material's last.
struct CryptomatteHashes {
    std::vector<uint32_t> objects, materials;
    explicit CryptomatteHashes(const Scene& scene);
    uint32_t object(uint32_t instance) const { return objects[instance]; }
    uint32_t material(int m) const { return m >= 0 ? materials[size_t(m)] : materials.back(); }
};

// The layers' type names (Blender's): Typename00, 01, 02 hold the ranks.
inline constexpr const char* kCryptoObjectLayer = "CryptoObject";
inline constexpr const char* kCryptoMaterialLayer = "CryptoMaterial";
// The header entries of one layer: its name, hash, conversion and manifest, under
// cryptomatte_key.
std::vector<std::pair<std::string, std::string>> cryptomatte_header(
    const std::string& layer, const std::vector<std::string>& names);

// The ranks written per layer (two per RGBA layer: Typename00, 01, 02), Blender's
// default "levels".
inline constexpr int kCryptomatteRanks = 6;
// The IDs a pixel holds; a further ID's samples are dropped (counted as misses).
inline constexpr int kCryptomatteSlots = 8;

// One pixel's IDs and their summed filter weights, in first-seen order.
struct CryptomatteSlots {
    std::array<uint32_t, kCryptomatteSlots> hash{};
    std::array<float, kCryptomatteSlots> weight{};  // 0: an empty slot
    void add(uint32_t id, float w) {
        for (int i = 0; i < kCryptomatteSlots; ++i) {
            if (weight[i] > 0 && hash[i] != id) continue;
            hash[i] = id;
            weight[i] += w;
            return;
        }
    }
    // The IDs by coverage (weight over total), largest first, ties by hash; at most
    // kCryptomatteRanks, the rest (id 0, coverage 0) empty.
    std::array<std::pair<float, float>, kCryptomatteRanks> ranked(double total) const;
};

}  // namespace penumbra
