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
    // A 1D value drawn now and perhaps read later (value(), at most once): the default
    // sampler leaves its hash and table load to the read, which a caller that turns out
    // not to need the value skips. Other samplers draw it here.
    class Deferred1d {
        friend class PathSampler;
        uint64_t key = 0;
        float value = 0;
    };
    Deferred1d defer_1d() {
        Deferred1d d;
        if (m_tabled)
            d.key = m_tabled->skip_1d();
        else
            d.value = m_any.get_1d();
        return d;
    }
    float value(const Deferred1d& d) const {
        return m_tabled ? m_tabled->value_1d(d.key) : d.value;
    }
    Sampler& sampler() { return m_any; }

private:
    Sampler& m_any;
    TabledSobolSampler* m_tabled;
};

}  // namespace penumbra
