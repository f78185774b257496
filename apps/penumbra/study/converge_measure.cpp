#include "apps/penumbra/study/converge_measure.h"

#include <cmath>
#include <cstdio>
#include <memory>

#include "apps/penumbra/denoise_step.h"
#include "apps/penumbra/scene_setup.h"
#include "core/film/image_error.h"
#include "core/error.h"
#include "core/progress.h"

namespace penumbra {

namespace {

// Mean over pixels and R, G, B of the film's estimated variance / (r^2 + epsilon): the
// variance part of its relMSE against r.
double relative_variance(const Film& film, const Image& ref, double epsilon) {
    double sum = 0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Spectrum v = film.estimated_variance(x, y);
            for (int c = 0; c < 3; ++c) {
                const double r = ref.at(x, y)[c];
                sum += v[c] / (r * r + epsilon);
            }
        }
    return sum / (3.0 * film.width() * film.height());
}

// The renders of one configuration: doubling spp, one per time limit, or (adaptive) the
// target halving in relMSE per checkpoint.
std::vector<RenderOptions> plan_runs(const ConvergeOptions& o, RenderOptions ropt) {
    std::vector<RenderOptions> runs;
    if (ropt.target_error > 0) {
        // Adaptive: the target halves in relMSE (E / sqrt 2) per checkpoint, ending at
        // the configuration's, as many checkpoints as the spp sweep has; --max-spp caps.
        ropt.spp = o.max_spp;
        int count = 0;
        for (uint64_t spp = o.min_spp; spp <= o.max_spp; spp *= 2) ++count;
        const double last = ropt.target_error;
        for (int k = count - 1; k >= 0; --k) {
            ropt.target_error = last * std::pow(2.0, 0.5 * k);
            runs.push_back(ropt);
        }
    } else if (o.times.empty()) {
        for (uint64_t spp = o.min_spp; spp <= o.max_spp; spp *= 2) {
            ropt.spp = static_cast<uint32_t>(spp);
            runs.push_back(ropt);
        }
    } else {
        ropt.spp = o.max_spp;
        for (double t : o.times) {
            ropt.time_limit = t;
            runs.push_back(ropt);
        }
    }
    return runs;
}

// The render denoised, measured as the render was; its time adds the denoiser's.
ConvergePoint denoised_point(const ConvergeOptions& o, const ConvergeConfig& c, const Film& film,
                             const Image& ref, ConvergePoint p) {
    const double cpu0 = process_cpu_seconds();
    const std::unique_ptr<DenoiseStep> step = denoise_film(film, c.options.threads);
    p.seconds += step->seconds;
    p.cpu_seconds += process_cpu_seconds() - cpu0;
    p.mse = mean_squared_error(step->result.color, ref);
    p.relmse = relative_mse(step->result.color, ref, o.epsilon);
    p.variance = 0;  // the halves describe the raw image only
    p.relmse_estimate = step->result.relmse_estimate;
    return p;
}

void print_point(const ConvergeOptions& o, const std::string& name, const ConvergePoint& p,
                 const ConvergePoint* denoised) {
    char variance[64] = "", dn[96] = "";
    if (o.bias_variance) std::snprintf(variance, sizeof variance, "  variance %.4e", p.variance);
    if (denoised)
        std::snprintf(dn, sizeof dn, "  denoised relMSE %.4e (estimate %.4e)", denoised->relmse,
                      denoised->relmse_estimate);
    std::printf("%-14s %7u spp (mean %7.1f) %8s (cpu %8s)  MSE %.4e  relMSE %.4e%s%s\n",
                name.c_str(), p.spp, p.mean_spp, format_duration(p.seconds).c_str(),
                format_duration(p.cpu_seconds).c_str(), p.mse, p.relmse, variance, dn);
    std::fflush(stdout);
}

}  // namespace

std::vector<ConvergeSeries> measure_config(const ConvergeOptions& o, const ConvergeConfig& c,
                                           const Image& ref) {
    const std::unique_ptr<SceneSetup> s = setup_scene(c.options, o.scene);
    if (s->width != ref.width || s->height != ref.height)
        throw SceneError("configuration '" + c.name + "' renders " + std::to_string(s->width) +
                         "x" + std::to_string(s->height) + " but the reference is " +
                         std::to_string(ref.width) + "x" + std::to_string(ref.height));
    RenderOptions ropt = render_options_for(c.options, c.name);
    ropt.progress = false;
    if (o.bias_variance) ropt.aovs.add(Aov::Error);
    std::vector<ConvergeSeries> series = {{c.name, c.name, false, {}}};
    if (c.options.denoise) series.push_back({c.name + " denoised", c.name, true, {}});
    for (const RenderOptions& run : plan_runs(o, ropt)) {
        RenderStats stats;
        const double cpu0 = process_cpu_seconds();
        const Film film = render(s->context(), *s->camera, *s->integrator, run, &stats);
        const Image img = film.resolve();
        ConvergePoint p{stats.spp, stats.seconds, process_cpu_seconds() - cpu0,
                        mean_squared_error(img, ref), relative_mse(img, ref, o.epsilon)};
        if (o.bias_variance) p.variance = relative_variance(film, ref, o.epsilon);
        p.mean_spp = double(stats.camera_samples) / (double(img.width) * img.height);
        p.target_error = run.target_error;
        series[0].points.push_back(p);
        // Below 2 spp one half of each pixel's samples is empty: nothing to denoise with,
        // so the denoised series starts at 2.
        const bool denoise = c.options.denoise && stats.spp >= 2;
        if (denoise) series[1].points.push_back(denoised_point(o, c, film, ref, p));
        if (!c.options.quiet)
            print_point(o, c.name, p, denoise ? &series[1].points.back() : nullptr);
    }
    return series;
}

}  // namespace penumbra
