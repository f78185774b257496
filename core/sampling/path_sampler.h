// A path's draws from its sampler, with the default sampler's inlined. The path loop
// draws about five values a vertex; through Sampler's virtual functions each is a call
// the compiler cannot inline or schedule around. TabledSobolSampler (the default, final)
// gets direct calls, inlined; any other sampler goes through the base class as before,
// so every sampler draws the same values in the same order either way.
#pragma once

#include <typeinfo>

#include "core/sampling/sampler.h"
#include "core/sampling/tabled_sobol_sampler.h"

namespace penumbra {

class PathSampler {
public:
    explicit PathSampler(Sampler& s)
        : m_any(s),
          m_tabled(typeid(s) == typeid(TabledSobolSampler) ? static_cast<TabledSobolSampler*>(&s)
                                                           : nullptr) {}
    // The branch goes the same way for a whole render: predicted, it costs nothing.
    float get_1d() { return m_tabled ? m_tabled->get_1d() : m_any.get_1d(); }
    Vec2 get_2d() { return m_tabled ? m_tabled->get_2d() : m_any.get_2d(); }
    Sampler& sampler() { return m_any; }

private:
    Sampler& m_any;
    TabledSobolSampler* m_tabled;
};

}  // namespace penumbra
