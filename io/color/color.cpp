#include "io/color/color.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "core/error.h"
#include "core/log.h"
#include "io/color/color_config.h"

namespace penumbra {

struct ColorPipeline::Impl {
    OCIO::ConstConfigRcPtr config;
    std::string source, working, output, display, view, look;
    Mat3 rec709_to_working = Mat3::identity();
    bool working_is_rec709 = true;
    OCIO::ConstCPUProcessorRcPtr to_output;  // null: output space = working space
    OCIO::ConstCPUProcessorRcPtr to_display;
    std::optional<Chromaticities> output_chromaticities;
};

namespace {

// OCIO's default optimisation approximates pow/log (OPTIMIZATION_FAST_LOG_EXP_POW);
// lossless keeps the sRGB curve exact to float precision and files reproducible.
OCIO::ConstCPUProcessorRcPtr cpu(const OCIO::ConstProcessorRcPtr& p) {
    return p->getOptimizedCPUProcessor(OCIO::OPTIMIZATION_LOSSLESS);
}

std::string one_line(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    return s;
}

std::string list_spaces(const OCIO::ConstConfigRcPtr& c) {
    std::string names;
    for (int i = 0; i < c->getNumColorSpaces(); ++i)
        names += (i ? ", " : "") + std::string(c->getColorSpaceNameByIndex(i));
    return names;
}

// The canonical name of a colour space, alias or role; throws naming what was asked.
OCIO::ConstColorSpaceRcPtr find_space(const OCIO::ConstConfigRcPtr& config,
                                      const std::string& source, const std::string& name,
                                      const char* option) {
    OCIO::ConstColorSpaceRcPtr cs = config->getColorSpace(name.c_str());
    if (!cs)
        throw SceneError(source + ": " + option + " '" + name +
                         "': no such colour space (the config has " + list_spaces(config) + ")");
    return cs;
}

std::vector<std::string> views_of(const OCIO::ConstConfigRcPtr& c, const std::string& display) {
    std::vector<std::string> v;
    for (int i = 0; i < c->getNumViews(display.c_str()); ++i)
        v.push_back(c->getView(display.c_str(), i));
    return v;
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

struct DisplayChoice {
    std::string source, working, display, view, look;
    OCIO::ConstCPUProcessorRcPtr processor;
};

void choose_display(const OCIO::ConstConfigRcPtr& c, DisplayChoice& m, const ColorSettings& s) {
    std::vector<std::string> displays;
    for (int i = 0; i < c->getNumDisplaysAll(); ++i) displays.push_back(c->getDisplayAll(i));
    m.display = s.display.empty() ? c->getDefaultDisplay() : s.display;
    if (std::find(displays.begin(), displays.end(), m.display) == displays.end())
        throw SceneError(m.source + ": --display '" + m.display +
                         "': no such display (the config has " + join(displays) + ")");
    const std::vector<std::string> views = views_of(c, m.display);
    m.view = s.view.empty() ? c->getDefaultView(m.display.c_str()) : s.view;
    if (std::find(views.begin(), views.end(), m.view) == views.end())
        throw SceneError(m.source + ": --view '" + m.view + "': display '" + m.display +
                         "' has no such view (it has " + join(views) + ")");
    m.look = s.look;
    // A look list is "a, b" or "+a:-b"; each name must exist.
    std::string token;
    for (size_t i = 0; i <= m.look.size(); ++i) {
        const char ch = i < m.look.size() ? m.look[i] : ',';
        if (ch != ',' && ch != ':') {
            token += ch;
            continue;
        }
        token.erase(0, token.find_first_not_of(" +-"));
        token.erase(token.find_last_not_of(' ') + 1);
        if (!token.empty() && !c->getLook(token.c_str())) {
            std::vector<std::string> looks;
            for (int k = 0; k < c->getNumLooks(); ++k) looks.push_back(c->getLookNameByIndex(k));
            throw SceneError(m.source + ": --look '" + token + "': no such look (the config has " +
                             (looks.empty() ? std::string("none") : join(looks)) + ")");
        }
        token.clear();
    }
    auto dvt = OCIO::DisplayViewTransform::Create();
    dvt->setSrc(m.working.c_str());
    dvt->setDisplay(m.display.c_str());
    dvt->setView(m.view.c_str());
    OCIO::LegacyViewingPipelineRcPtr vp = OCIO::LegacyViewingPipeline::Create();
    vp->setDisplayViewTransform(dvt);
    if (!m.look.empty()) {
        vp->setLooksOverrideEnabled(true);
        vp->setLooksOverride(m.look.c_str());
    }
    m.processor = cpu(vp->getProcessor(c));
}

}  // namespace

ColorPipeline::ColorPipeline(const ColorSettings& s) : m(std::make_unique<Impl>()) {
    const char* env = std::getenv("OCIO");
    const std::string file = !s.config.empty() ? s.config : (env && *env ? env : "");
    try {
        if (file.empty() || file == "builtin") {
            m->config = builtin_config();
            m->source = "built-in OCIO config";
        } else {
            m->source = s.config.empty() ? "$OCIO=" + file : file;
            m->config = OCIO::Config::CreateFromFile(file.c_str());
        }
    } catch (const OCIO::Exception& e) {
        throw SceneError(m->source + ": cannot load the OCIO config: " + one_line(e.what()));
    }

    try {
        if (s.working_space.empty() && !m->config->hasRole(OCIO::ROLE_SCENE_LINEAR))
            throw SceneError(m->source +
                             ": the config has no scene_linear role; choose a "
                             "space with --working-space");
        OCIO::ConstColorSpaceRcPtr w = find_space(
            m->config, m->source,
            s.working_space.empty() ? OCIO::ROLE_SCENE_LINEAR : s.working_space, "--working-space");
        m->working = w->getName();
        if (w->isData() || w->getReferenceSpaceType() != OCIO::REFERENCE_SPACE_SCENE)
            throw SceneError(m->source + ": --working-space '" + m->working +
                             "' is data or display-referred, not a scene-linear space");
        if (!m->config->hasRole(OCIO::ROLE_INTERCHANGE_SCENE) &&
            !m->config->hasRole(OCIO::ROLE_INTERCHANGE_DISPLAY)) {
            LOG_WARNING(m->source << ": the config has no aces_interchange or "
                                     "cie_xyz_d65_interchange role to relate its spaces to "
                                     "Rec.709; glTF colours go into '"
                                  << m->working << "' unconverted");
        } else {
            const std::optional<Mat3> w_xyz = to_xyz_d65(m->working);
            Mat3 xyz_to_w;
            if (!w_xyz || !w_xyz->inverse(&xyz_to_w))
                throw SceneError(m->source + ": --working-space '" + m->working +
                                 "' is not a linear RGB space");
            // Recognised as Rec.709 (chromaticities_from_xyz_d65's tolerance): configs
            // spell its matrix with more or fewer digits (Blender's differs by 1.6e-4),
            // which should not make glTF colours drift by a rounding error.
            const Mat3 rec709 = rgb_to_xyz_d65(rec709_chromaticities());
            m->working_is_rec709 = rec709.max_difference(*w_xyz) <= 2e-3;
            m->rec709_to_working = m->working_is_rec709 ? Mat3::identity() : xyz_to_w * rec709;
        }

        m->output = s.output_space.empty()
                        ? m->working
                        : find_space(m->config, m->source, s.output_space, "--output-colorspace")
                              ->getName();
        if (m->output != m->working)
            m->to_output = cpu(m->config->getProcessor(m->working.c_str(), m->output.c_str()));
        if (const std::optional<Mat3> o = to_xyz_d65(m->output))
            m->output_chromaticities = chromaticities_from_xyz_d65(*o);
        else
            LOG_INFO(m->source << ": output space '" << m->output
                               << "' is not linear; the EXR gets no chromaticities");
        DisplayChoice d{m->source, m->working, "", "", "", nullptr};
        choose_display(m->config, d, s);
        m->display = d.display;
        m->view = d.view;
        m->look = d.look;
        m->to_display = d.processor;
    } catch (const OCIO::Exception& e) {
        throw SceneError(m->source + ": " + one_line(e.what()));
    }
}

ColorPipeline::~ColorPipeline() = default;
ColorPipeline::ColorPipeline(ColorPipeline&&) noexcept = default;
ColorPipeline& ColorPipeline::operator=(ColorPipeline&&) noexcept = default;

const ColorPipeline& ColorPipeline::builtin() {
    static const ColorPipeline p([] {
        ColorSettings s;
        s.config = "builtin";
        return s;
    }());
    return p;
}

const std::string& ColorPipeline::config_source() const { return m->source; }
const std::string& ColorPipeline::working_space() const { return m->working; }
const std::string& ColorPipeline::output_space() const { return m->output; }
const std::string& ColorPipeline::display() const { return m->display; }
const std::string& ColorPipeline::view() const { return m->view; }
const std::string& ColorPipeline::look() const { return m->look; }
const Mat3& ColorPipeline::rec709_to_working() const { return m->rec709_to_working; }
bool ColorPipeline::working_is_rec709() const { return m->working_is_rec709; }
const std::optional<Chromaticities>& ColorPipeline::output_chromaticities() const {
    return m->output_chromaticities;
}

std::optional<Mat3> ColorPipeline::to_xyz_d65(const std::string& space) const {
    const OCIO::ConstConfigRcPtr& c = m->config;
    OCIO::ConstColorSpaceRcPtr cs = c->getColorSpace(space.c_str());
    // Data spaces pass through every conversion unchanged, which would look linear.
    if (!cs || cs->isData()) return std::nullopt;
    auto group = OCIO::GroupTransform::Create();
    auto to_interchange = OCIO::ColorSpaceTransform::Create();
    to_interchange->setSrc(cs->getName());
    if (c->hasRole(OCIO::ROLE_INTERCHANGE_SCENE)) {
        to_interchange->setDst(OCIO::ROLE_INTERCHANGE_SCENE);
        group->appendTransform(to_interchange);
        // The aces_interchange role is ACES2065-1 by definition (OCIO 2.1 docs).
        auto ap0 = OCIO::BuiltinTransform::Create();
        ap0->setStyle("UTILITY - ACES-AP0_to_CIE-XYZ-D65_BFD");
        group->appendTransform(ap0);
    } else if (c->hasRole(OCIO::ROLE_INTERCHANGE_DISPLAY)) {
        to_interchange->setDst(OCIO::ROLE_INTERCHANGE_DISPLAY);
        group->appendTransform(to_interchange);
    } else {
        return std::nullopt;
    }
    OCIO::ConstCPUProcessorRcPtr p;
    try {
        p = cpu(c->getProcessor(group));
    } catch (const OCIO::Exception& e) {
        LOG_WARNING(m->source << ": cannot relate '" << space
                              << "' to CIE XYZ: " << one_line(e.what()));
        return std::nullopt;
    }
    Vec3 col[3];
    for (int j = 0; j < 3; ++j) {
        float e[3] = {0, 0, 0};
        e[j] = 1;
        p->applyRGB(e);
        col[j] = {e[0], e[1], e[2]};
    }
    const Mat3 M = Mat3::from_columns(col[0], col[1], col[2]);
    // Linear means the matrix predicts other inputs too, small and large: a transfer
    // curve or a log encoding fails this by far more than float rounding.
    for (const Vec3 v : {Vec3(0.02f, 0.05f, 0.01f), Vec3(0.3f, 0.6f, 0.1f), Vec3(4, 9, 2)}) {
        float e[3] = {v.x, v.y, v.z};
        p->applyRGB(e);
        const Vec3 expect = M * v;
        for (int i = 0; i < 3; ++i)
            if (!(std::abs(e[i] - expect[i]) <= 1e-4f * (std::abs(expect[i]) + 1e-2f)))
                return std::nullopt;
    }
    return M;
}

void ColorPipeline::convert(float* rgb, size_t count, const std::string& from,
                            const std::string& to) const {
    try {
        OCIO::ConstCPUProcessorRcPtr p = cpu(m->config->getProcessor(from.c_str(), to.c_str()));
        OCIO::PackedImageDesc desc(rgb, long(count), 1, 3);
        p->apply(desc);
    } catch (const OCIO::Exception& e) {
        throw SceneError(m->source + ": " + one_line(e.what()));
    }
}

void ColorPipeline::to_output(Image& image) const {
    if (!m->to_output || image.pixels.empty()) return;
    CHECK(image.channels == 3 || image.channels == 4);
    OCIO::PackedImageDesc desc(image.pixels.data(), image.width, image.height, image.channels);
    m->to_output->apply(desc);
}

Image ColorPipeline::to_display(const Image& working, float exposure) const {
    Image out(working.width, working.height, 3);
    const float scale = std::exp2(exposure);
    const size_t n = size_t(working.width) * working.height;
    const int colour = working.channels >= 3 ? 3 : 1;  // gray images spread to RGB
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c)
            out.pixels[3 * i + c] =
                working.pixels[i * working.channels + (colour == 3 ? c : 0)] * scale;
    if (n) {
        OCIO::PackedImageDesc desc(out.pixels.data(), out.width, out.height, 3);
        m->to_display->apply(desc);
    }
    for (float& v : out.pixels) v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    return out;
}

namespace {

// The built-in sRGB curve, both ways; built once.
const OCIO::ConstCPUProcessorRcPtr& srgb_processor(bool decode) {
    static const OCIO::ConstCPUProcessorRcPtr to_linear =
        cpu(builtin_config()->getProcessor(kSrgbEncoded, kLinearRec709));
    static const OCIO::ConstCPUProcessorRcPtr to_srgb =
        cpu(builtin_config()->getProcessor(kLinearRec709, kSrgbEncoded));
    return decode ? to_linear : to_srgb;
}

}  // namespace

float srgb_to_linear(float encoded) {
    float v[3] = {encoded, encoded, encoded};
    srgb_processor(true)->applyRGB(v);
    return v[0];
}

float linear_to_srgb(float linear) {
    float v[3] = {linear, linear, linear};
    srgb_processor(false)->applyRGB(v);
    return v[0];
}

void decode_srgb(Image& image) {
    const int ch = image.channels;
    if (image.pixels.empty()) return;
    if (ch == 3 || ch == 4) {
        OCIO::PackedImageDesc desc(image.pixels.data(), image.width, image.height, ch);
        srgb_processor(true)->apply(desc);
        return;
    }
    // Gray (with or without alpha): the curve is per channel, so spread gray to RGB.
    const size_t n = size_t(image.width) * image.height;
    std::vector<float> rgb(3 * n);
    for (size_t i = 0; i < n; ++i)
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = image.pixels[i * ch];
    OCIO::PackedImageDesc desc(rgb.data(), long(n), 1, 3);
    srgb_processor(true)->apply(desc);
    for (size_t i = 0; i < n; ++i) image.pixels[i * ch] = rgb[3 * i];
}

}  // namespace penumbra
