#include "core/film/image_error.h"

#include "core/error.h"

namespace penumbra {

namespace {

template <typename F>
double mean_over_rgb(const Image& image, const Image& reference, F per_channel) {
    CHECK(image.width == reference.width && image.height == reference.height,
          "image " << image.width << "x" << image.height << " vs reference "
                   << reference.width << "x" << reference.height);
    double sum = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const Vec4 a = image.rgba(x, y), r = reference.rgba(x, y);
            sum += per_channel(a.x, r.x) + per_channel(a.y, r.y) + per_channel(a.z, r.z);
        }
    const double n = 3.0 * image.width * image.height;
    return n > 0 ? sum / n : 0;
}

}  // namespace

double mean_squared_error(const Image& image, const Image& reference) {
    return mean_over_rgb(image, reference, [](double a, double r) { return (a - r) * (a - r); });
}

double relative_mse(const Image& image, const Image& reference, double epsilon) {
    return mean_over_rgb(image, reference, [epsilon](double a, double r) {
        return (a - r) * (a - r) / (r * r + epsilon);
    });
}

}  // namespace penumbra
