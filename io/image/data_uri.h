// RFC 2397 data: URIs with base64 payloads, for image MIME types tinygltf does not
// decode itself (image/ktx2, image/webp): it only knows PNG, JPEG, BMP, GIF and
// octet-stream, and takes any other data: URI for a file name.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace penumbra {

// The payload of "data:<mime>;base64,<data>", or false when `uri` is not of that form or
// its base64 is malformed (a character outside the alphabet, bad padding).
bool decode_data_uri(const std::string& uri, std::vector<uint8_t>* out);

}  // namespace penumbra
