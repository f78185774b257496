#include "core/film/cryptomatte.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <unordered_set>

namespace penumbra {

namespace {

uint32_t rotl32(uint32_t x, int r) { return (x << r) | (x >> (32 - r)); }

std::string hex8(uint32_t h) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x", h);
    return buf;
}

// A JSON string literal.
std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

}  // namespace

uint32_t cryptomatte_hash(std::string_view name) {
    // MurmurHash3_x86_32 (Austin Appleby, public domain), seed 0.
    const uint32_t c1 = 0xcc9e2d51, c2 = 0x1b873593;
    const size_t n = name.size(), blocks = n / 4;
    uint32_t h = 0;
    for (size_t i = 0; i < blocks; ++i) {
        uint32_t k;
        std::memcpy(&k, name.data() + 4 * i, 4);  // little-endian, as the reference reads
        k = rotl32(k * c1, 15) * c2;
        h = rotl32(h ^ k, 13) * 5 + 0xe6546b64;
    }
    const auto* tail = reinterpret_cast<const unsigned char*>(name.data() + 4 * blocks);
    uint32_t k = 0;
    switch (n & 3) {
        case 3:
            k ^= uint32_t(tail[2]) << 16;
            [[fallthrough]];
        case 2:
            k ^= uint32_t(tail[1]) << 8;
            [[fallthrough]];
        case 1:
            k ^= tail[0];
            h ^= rotl32(k * c1, 15) * c2;
    }
    h ^= uint32_t(n);
    h ^= h >> 16;
    h *= 0x85ebca6b;
    h ^= h >> 13;
    h *= 0xc2b2ae35;
    h ^= h >> 16;
    return h;
}

float cryptomatte_float(uint32_t hash) {
    const uint32_t exponent = hash >> 23 & 255;
    if (exponent == 0 || exponent == 255) hash ^= 1u << 23;
    float f;
    std::memcpy(&f, &hash, 4);
    return f;
}

std::string cryptomatte_manifest(const std::vector<std::string>& names) {
    std::string out = "{";
    std::unordered_set<std::string_view> seen;  // a million instances may share a name
    for (const std::string& name : names) {
        if (!seen.insert(name).second) continue;
        out += (seen.size() > 1 ? "," : "") + quoted(name) + ":" +
               quoted(hex8(cryptomatte_hash(name)));
    }
    return out + "}";
}

std::string cryptomatte_key(const std::string& layer, const std::string& entry) {
    return "cryptomatte/" + hex8(cryptomatte_hash(layer)).substr(0, 7) + "/" + entry;
}

std::vector<std::pair<std::string, std::string>> cryptomatte_header(
    const std::string& layer, const std::vector<std::string>& names) {
    return {{cryptomatte_key(layer, "name"), layer},
            {cryptomatte_key(layer, "hash"), "MurmurHash3_32"},
            {cryptomatte_key(layer, "conversion"), "uint32_to_float32"},
            {cryptomatte_key(layer, "manifest"), cryptomatte_manifest(names)}};
}

std::string cryptomatte_object_name(const Scene& scene, uint32_t instance) {
    // EXT_mesh_gpu_instancing's copies carry no name: their node's path names them.
    const Instance& inst = scene.instances[instance];
    return !inst.name.empty() ? inst.name : "nodes[" + std::to_string(inst.node) + "]";
}

const std::string& cryptomatte_material_name(const Scene& scene, int material) {
    static const std::string kDefault = "default";
    return material >= 0 ? scene.materials[size_t(material)].name : kDefault;
}

std::vector<std::string> cryptomatte_object_names(const Scene& scene) {
    std::vector<std::string> names;
    for (uint32_t i = 0; i < scene.instances.size(); ++i)
        names.push_back(cryptomatte_object_name(scene, i));
    return names;
}

std::vector<std::string> cryptomatte_material_names(const Scene& scene) {
    std::vector<std::string> names;
    for (int i = 0; i < int(scene.materials.size()); ++i)
        names.push_back(cryptomatte_material_name(scene, i));
    names.push_back(cryptomatte_material_name(scene, -1));
    return names;
}

CryptomatteHashes::CryptomatteHashes(const Scene& scene) {
    for (const std::string& name : cryptomatte_object_names(scene))
        objects.push_back(cryptomatte_hash(name));
    for (const std::string& name : cryptomatte_material_names(scene))
        materials.push_back(cryptomatte_hash(name));
}

std::array<std::pair<float, float>, kCryptomatteRanks> CryptomatteSlots::ranked(
    double total) const {
    std::array<int, kCryptomatteSlots> order;
    for (int i = 0; i < kCryptomatteSlots; ++i) order[size_t(i)] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        if (weight[size_t(a)] != weight[size_t(b)]) return weight[size_t(a)] > weight[size_t(b)];
        return hash[size_t(a)] < hash[size_t(b)];
    });
    std::array<std::pair<float, float>, kCryptomatteRanks> out{};
    for (int r = 0; r < kCryptomatteRanks && r < kCryptomatteSlots; ++r) {
        const int i = order[size_t(r)];
        if (!(weight[size_t(i)] > 0) || !(total > 0)) break;
        out[size_t(r)] = {cryptomatte_float(hash[size_t(i)]), float(weight[size_t(i)] / total)};
    }
    return out;
}

}  // namespace penumbra
