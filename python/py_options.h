// Python keyword arguments to render options. Each key is a declared option
// (job/option_table.h) by its job-file key ("time_limit") or its flag with '_' for '-'
// ("threads"); each value has the JSON type a job file gives it. The values go through the
// job file's own conversion and `set`, so every option the CLI has is a keyword, with the
// same checks, and a new option needs nothing here.
#pragma once

#include <pybind11/pybind11.h>

#include "job/render_options.h"

namespace penumbra::python {

// o with kwargs set over it, in order, as a job entry's keys go over its defaults.
// Throws pybind11::value_error naming the key and what is wrong with its value.
RenderCommandOptions options_with(const RenderCommandOptions& o, const pybind11::dict& kwargs);

// The module's defaults: the CLI's, but quiet (no progress bars on stderr).
RenderCommandOptions module_defaults();

// penumbra.options(): the option reference, from the same table as `penumbra render --help`.
void bind_options(pybind11::module_& m);

}  // namespace penumbra::python
