// The builders of job/option_table.cpp's declarations: one per kind of value, each
// making an OptionDecl's get, set and header from the field it is given.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "job/option_table.h"

namespace penumbra::option_builders {

inline const double kInf = std::numeric_limits<double>::infinity();

// When the header records an option.
enum class Header {
    None,           // never
    Always,         // its text
    WhenPositive,   // its text, when above 0 (off otherwise)
    WhenSet,        // its text, when set
    AsFloat,        // a float attribute
    WithAdaptive,   // its text, with adaptive sampling on
};

struct Meta {
    const char* flag;
    const char* job_key;     // "" : none
    const char* header_key;  // "" : none
    bool pixels;
    OptionScope scope;
    const char* help;
    Header header = Header::None;
};

inline constexpr bool kPixels = true, kNotPixels = false;
inline constexpr OptionScope kImage = OptionScope::Image, kRender = OptionScope::Render,
                      kFarm = OptionScope::Farm;

inline OptionDecl declare(const Meta& m, OptionKind kind) {
    OptionDecl d;
    d.flag = m.flag;
    d.job_key = m.job_key;
    d.header_key = m.header_key;
    d.pixels = m.pixels;
    d.scope = m.scope;
    d.help = m.help;
    d.kind = kind;
    return d;
}

// Every digit a float or double needs to read back as itself: a value that differs in
// its last bit is another render to the fingerprint.
template <typename T>
std::string exact_text(T v) {
    std::ostringstream s;
    s.precision(std::numeric_limits<T>::max_digits10);
    s << v;
    return s.str();
}

template <typename T>
T parse_number(const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    T v{};
    if constexpr (std::is_floating_point_v<T>) {
        const double d = std::strtod(begin, &end);
        if (end != begin && !std::isfinite(d)) throw std::invalid_argument("must be finite");
        v = T(d);
    } else if constexpr (std::is_signed_v<T>) {
        const long long i = std::strtoll(begin, &end, 10);
        if (i < std::numeric_limits<T>::min() || i > std::numeric_limits<T>::max()) errno = ERANGE;
        v = T(i);
    } else {
        if (text.find('-') != std::string::npos)
            throw std::invalid_argument("'" + text + "' is negative");
        const unsigned long long u = std::strtoull(begin, &end, 10);
        if (u > std::numeric_limits<T>::max()) errno = ERANGE;
        v = T(u);
    }
    if (end == begin || *end != '\0')
        throw std::invalid_argument("'" + text + "' is not a" +
                                    (std::is_floating_point_v<T> ? " number" : "n integer"));
    if (errno == ERANGE) throw std::invalid_argument("'" + text + "' is out of range");
    return v;
}

inline std::string range_text(double lo, double hi, bool lo_open) {
    std::ostringstream s;
    s.precision(15);  // whole bounds print whole: [1, 16777216]
    if (hi == kInf) {
        s << (lo_open ? "above " : "at least ") << lo;
    } else {
        s << "in [" << lo << ", " << hi << "]";
    }
    return s.str();
}

template <typename T>
std::optional<MetadataValue> header_of(Header h, T value, const std::string& text) {
    switch (h) {
        case Header::None: return std::nullopt;
        case Header::Always: break;
        case Header::WhenPositive:
            if (!(double(value) > 0)) return std::nullopt;
            break;
        case Header::WhenSet:
            if (text.empty()) return std::nullopt;
            break;
        case Header::AsFloat: return MetadataValue(float(value));
        case Header::WithAdaptive: break;  // the option's decl adds the condition
    }
    // std::to_string for numbers: the header's format ("0.500000"), not the exact text.
    if constexpr (std::is_floating_point_v<T>) return MetadataValue(std::to_string(value));
    return MetadataValue(text);
}

// A number in [lo, hi] (lo excluded when lo_open); T is an arithmetic type or an
// optional of one (unset: "").
template <typename T, typename F>
OptionDecl number(const Meta& m, F field, double lo, double hi, bool lo_open = false) {
    using V = std::decay_t<T>;
    OptionDecl d = declare(m, std::is_floating_point_v<V> ? OptionKind::Number : OptionKind::Integer);
    d.get = [field](const RenderCommandOptions& o) {
        const auto& f = field(const_cast<RenderCommandOptions&>(o));
        if constexpr (std::is_floating_point_v<V>) return exact_text(V(f));
        else return std::to_string(f);
    };
    d.set = [field, lo, hi, lo_open](RenderCommandOptions& o, const std::string& text) {
        const V v = parse_number<V>(text);
        if (!(lo_open ? double(v) > lo : double(v) >= lo) || !(double(v) <= hi))
            throw std::invalid_argument(text + " is not " + range_text(lo, hi, lo_open));
        field(o) = v;
    };
    const Header h = m.header;
    d.header = [field, h](const RenderCommandOptions& o) {
        const V v = field(const_cast<RenderCommandOptions&>(o));
        std::string text;
        if constexpr (std::is_floating_point_v<V>) text = exact_text(v);
        else text = std::to_string(v);
        return header_of(h, v, text);
    };
    return d;
}

// An optional number (the timeline's): unset is "", which is also how it is cleared.
template <typename V, typename F>
OptionDecl optional_number(const Meta& m, F field, double lo, double hi) {
    OptionDecl d = declare(m, std::is_floating_point_v<V> ? OptionKind::Number : OptionKind::Integer);
    d.get = [field](const RenderCommandOptions& o) -> std::string {
        const std::optional<V>& f = field(const_cast<RenderCommandOptions&>(o));
        if (!f) return "";
        if constexpr (std::is_floating_point_v<V>) return exact_text(*f);
        else return std::to_string(*f);
    };
    d.set = [field, lo, hi](RenderCommandOptions& o, const std::string& text) {
        if (text.empty()) {
            field(o).reset();
            return;
        }
        const V v = parse_number<V>(text);
        if (!(double(v) >= lo && double(v) <= hi))
            throw std::invalid_argument(text + " is not " + range_text(lo, hi, false));
        field(o) = v;
    };
    const Header h = m.header;
    d.header = [field, h](const RenderCommandOptions& o) -> std::optional<MetadataValue> {
        const std::optional<V>& f = field(const_cast<RenderCommandOptions&>(o));
        if (!f || h == Header::None) return std::nullopt;
        return MetadataValue(std::to_string(*f));
    };
    return d;
}

template <typename F>
OptionDecl flag(const Meta& m, F field) {
    OptionDecl d = declare(m, OptionKind::Flag);
    d.get = [field](const RenderCommandOptions& o) {
        return std::string(field(const_cast<RenderCommandOptions&>(o)) ? "1" : "0");
    };
    d.set = [field](RenderCommandOptions& o, const std::string& text) {
        if (text != "0" && text != "1")
            throw std::invalid_argument("'" + text + "' is not 0 or 1");
        field(o) = text == "1";
    };
    const Header h = m.header;
    d.header = [field, h](const RenderCommandOptions& o) -> std::optional<MetadataValue> {
        if (h == Header::None) return std::nullopt;
        return MetadataValue(std::string(field(const_cast<RenderCommandOptions&>(o)) ? "1" : "0"));
    };
    return d;
}

template <typename F>
OptionDecl text(const Meta& m, F field, OptionKind kind = OptionKind::Text) {
    OptionDecl d = declare(m, kind);
    d.get = [field](const RenderCommandOptions& o) {
        return std::string(field(const_cast<RenderCommandOptions&>(o)));
    };
    d.set = [field](RenderCommandOptions& o, const std::string& text) { field(o) = text; };
    const Header h = m.header;
    d.header = [field, h](const RenderCommandOptions& o) {
        const std::string& v = field(const_cast<RenderCommandOptions&>(o));
        return h == Header::None || (h == Header::WhenSet && v.empty())
                   ? std::nullopt
                   : std::optional<MetadataValue>(v);
    };
    return d;
}

template <typename F>
OptionDecl path(const Meta& m, F field, bool existing_file = false) {
    OptionDecl d = text(m, field, OptionKind::Path);
    d.existing_file = existing_file;
    return d;
}

template <typename E>
struct Name {
    const char* name;
    E value;
};

// One of the names, each standing for a value of E.
template <typename E, typename F>
OptionDecl choice(const Meta& m, F field, std::vector<Name<E>> names) {
    OptionDecl d = declare(m, OptionKind::Choice);
    for (const Name<E>& n : names) d.choices.push_back(n.name);
    d.get = [field, names](const RenderCommandOptions& o) {
        const E v = field(const_cast<RenderCommandOptions&>(o));
        for (const Name<E>& n : names)
            if (n.value == v) return std::string(n.name);
        throw std::logic_error("an option's value has no name");
    };
    const std::string flag_name = m.flag;
    d.set = [field, names, flag_name](RenderCommandOptions& o, const std::string& text) {
        std::string list;
        for (const Name<E>& n : names) {
            if (text == n.name) {
                field(o) = n.value;
                return;
            }
            list += (list.empty() ? "" : ", ") + std::string(n.name);
        }
        throw std::invalid_argument("unknown " + flag_name + " '" + text + "' (expected one of: " +
                                    list + ")");
    };
    const Header h = m.header;
    auto get = d.get;
    d.header = [get, h](const RenderCommandOptions& o) {
        return h == Header::None ? std::nullopt : std::optional<MetadataValue>(get(o));
    };
    return d;
}

// `count` numbers, given as words separated by spaces; empty: not given.
template <typename F>
OptionDecl numbers(const Meta& m, F field, int count) {
    OptionDecl d = declare(m, OptionKind::Numbers);
    d.count = count;
    d.get = [field](const RenderCommandOptions& o) {
        std::string s;
        for (float v : field(const_cast<RenderCommandOptions&>(o)))
            s += (s.empty() ? "" : " ") + exact_text(v);
        return s;
    };
    d.set = [field, count](RenderCommandOptions& o, const std::string& text) {
        std::istringstream in(text);
        std::vector<float> values;
        std::string word;
        while (in >> word) values.push_back(parse_number<float>(word));
        if (!values.empty() && int(values.size()) != count)
            throw std::invalid_argument("needs " + std::to_string(count) + " numbers, got " +
                                        std::to_string(values.size()));
        field(o) = values;
    };
    d.header = [](const RenderCommandOptions&) { return std::nullopt; };
    return d;
}

inline OptionDecl timing(OptionDecl d) {
    d.timing = true;
    return d;
}

inline OptionDecl with_short(OptionDecl d, const char* short_flag) {
    d.short_flag = short_flag;
    return d;
}

}  // namespace penumbra::option_builders
