// Values by the names the command line gives them (job/option_table.h), so that tests can
// label their cases with those names.
#pragma once

#include <string>

#include "job/option_table.h"

namespace penumbra::test {

inline IntegratorType integrator_named(const std::string& name) {
    RenderCommandOptions o;
    set_render_option(o, "integrator", name);
    return o.integrator;
}

}  // namespace penumbra::test
