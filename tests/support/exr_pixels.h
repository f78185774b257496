// Reading an EXR's pixels in tests, and comparing two images bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace penumbra::test {

struct Pixels {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> data;  // every channel of every pixel, as float
    std::string error;        // empty when read
};

Pixels read_pixels(const std::string& path);

// Every channel of every pixel, bit for bit; the failure names the first differing pixel
// and how many differ.
::testing::AssertionResult same_pixels(const std::string& a, const std::string& b);

}  // namespace penumbra::test
