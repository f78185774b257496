#include "io/image/data_uri.h"

namespace penumbra {

namespace {

int base64_value(char c) {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

}  // namespace

bool decode_data_uri(const std::string& uri, std::vector<uint8_t>* out) {
    if (uri.compare(0, 5, "data:") != 0) return false;
    const size_t comma = uri.find(',');
    if (comma == std::string::npos || comma < 12 || uri.compare(comma - 7, 7, ";base64") != 0)
        return false;
    size_t end = uri.size();
    int padding = 0;
    while (end > comma + 1 && uri[end - 1] == '=' && padding < 2) {
        --end;
        ++padding;
    }
    const size_t n = end - comma - 1;
    if (padding && (n + size_t(padding)) % 4 != 0) return false;
    out->clear();
    out->reserve(n * 3 / 4);
    uint32_t acc = 0;
    int bits = 0;
    for (size_t i = comma + 1; i < end; ++i) {
        const int v = base64_value(uri[i]);
        if (v < 0) return false;
        acc = (acc << 6) | uint32_t(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out->push_back(uint8_t(acc >> bits));
            acc &= (1u << bits) - 1;
        }
    }
    return bits < 6;  // a lone sextet cannot end valid base64
}

}  // namespace penumbra
