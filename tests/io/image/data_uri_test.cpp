// data: URIs decoded for the MIME types tinygltf leaves alone (image/ktx2, image/webp).
#include "io/image/data_uri.h"

#include <gtest/gtest.h>

namespace penumbra {
namespace {

std::vector<uint8_t> bytes(const std::string& s) { return {s.begin(), s.end()}; }

TEST(DataUri, DecodesBase64WithAndWithoutPadding) {
    std::vector<uint8_t> out;
    ASSERT_TRUE(decode_data_uri("data:image/ktx2;base64,TWFu", &out));
    EXPECT_EQ(out, bytes("Man"));
    ASSERT_TRUE(decode_data_uri("data:image/ktx2;base64,TWE=", &out));
    EXPECT_EQ(out, bytes("Ma"));
    ASSERT_TRUE(decode_data_uri("data:image/webp;base64,TQ==", &out));
    EXPECT_EQ(out, bytes("M"));
    ASSERT_TRUE(decode_data_uri("data:image/ktx2;base64,q83v", &out));
    EXPECT_EQ(out, (std::vector<uint8_t>{0xAB, 0xCD, 0xEF}));
}

TEST(DataUri, RefusesWhatIsNotBase64Data) {
    std::vector<uint8_t> out;
    EXPECT_FALSE(decode_data_uri("t.ktx2", &out));
    EXPECT_FALSE(decode_data_uri("data:image/ktx2,raw", &out));     // not base64
    EXPECT_FALSE(decode_data_uri("data:image/ktx2;base64", &out));  // no comma
    EXPECT_FALSE(decode_data_uri("data:image/ktx2;base64,TW!u", &out));
    EXPECT_FALSE(decode_data_uri("data:image/ktx2;base64,TWFuT", &out));  // a lone sextet
    EXPECT_FALSE(decode_data_uri("data:image/ktx2;base64,TQ=", &out));    // bad padding
}

}  // namespace
}  // namespace penumbra
