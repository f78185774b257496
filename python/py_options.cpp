#include "python/py_options.h"

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "apps/penumbra/batch.h"
#include "core/error.h"
#include "job/job_file.h"
#include "job/option_table.h"

namespace py = pybind11;

namespace penumbra::python {

namespace {

const OptionDecl* python_option(const std::string& key) {
    if (const OptionDecl* d = find_option(key)) return d;
    std::string flag = key;
    std::replace(flag.begin(), flag.end(), '_', '-');
    return find_option(flag);
}

// Farm options split a job across tasks, and a frame list is many images: neither is one
// render's. Render frames one at a time with frame=N.
bool python_key(const OptionDecl& d) { return d.scope != OptionScope::Farm && d.flag != "frames"; }

// The keyword: the job key, else the flag with '_' for '-' (threads, checkpoint_interval).
std::string python_name(const OptionDecl& d) {
    std::string name = d.job_key.empty() ? d.flag : d.job_key;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

std::string known_keys() {
    std::string list;
    for (const OptionDecl& d : render_option_table())
        if (python_key(d))
            list += (list.empty() ? "" : ", ") + python_name(d);
    return list;
}

// The value as JSON, the form a job file gives it: numpy scalars and arrays become numbers
// and lists, paths (os.PathLike) strings.
nlohmann::json as_json(const py::handle& value) {
    const py::object dumps = py::module_::import("json").attr("dumps");
    const py::cpp_function plain([](const py::object& v) -> py::object {
        if (py::hasattr(v, "__fspath__")) return py::module_::import("os").attr("fspath")(v);
        if (py::hasattr(v, "tolist")) return v.attr("tolist")();
        throw py::type_error("cannot use a " + std::string(py::str(v.get_type())) + " here");
    });
    const std::string text = py::str(dumps(value, py::arg("default") = plain));
    return nlohmann::json::parse(text);
}

}  // namespace

RenderCommandOptions options_with(const RenderCommandOptions& o, const py::dict& kwargs) {
    JobSettings settings;
    RenderCommandOptions scratch;  // checks each value alone, naming its key
    const std::string cwd = std::filesystem::current_path().string();
    for (const auto& [k, v] : kwargs) {
        const std::string key = py::str(k);
        const OptionDecl* d = python_option(key);
        if (d && d->flag == "frames")
            throw py::value_error(key + ": render one frame at a time with frame=N");
        if (!d || !python_key(*d))
            throw py::value_error(key + ": unknown option (expected one of: " + known_keys() +
                                  ")");
        try {
            const std::string text = job_value_text(*d, as_json(v), cwd);
            d->set(scratch, text);
            settings.push_back({d, text});
        } catch (const std::invalid_argument& e) {
            throw py::value_error(key + ": " + e.what());
        } catch (const py::type_error& e) {
            throw py::value_error(key + ": " + e.what());
        }
    }
    RenderCommandOptions result = o;
    // `set`, not a job file's meaning of a key: frame=N is one frame, not a list of one.
    apply_settings(settings, result, /*job_keys=*/false);
    return result;
}

RenderCommandOptions module_defaults() {
    RenderCommandOptions o;
    o.quiet = true;
    return o;
}

void bind_options(py::module_& m) {
    m.def(
        "options",
        []() {
            py::dict out;
            for (const OptionDecl& d : render_option_table()) {
                if (!python_key(d)) continue;
                py::dict entry;
                entry["flag"] = "--" + d.flag;
                entry["help"] = d.help;
                entry["default"] = d.get ? d.get(RenderCommandOptions()) : std::string();
                entry["choices"] = d.choices;
                out[py::str(python_name(d))] = entry;
            }
            return out;
        },
        "Every render option a keyword argument of load() or Scene.render() takes: key -> "
        "{'flag', 'help', 'default', 'choices'}. The same table as `penumbra render --help` "
        "and job files; keys are job-file keys (flags with '_' for '-' also work).");
}

}  // namespace penumbra::python
