#include "job/aov_list.h"

#include <stdexcept>

namespace penumbra {

const std::vector<std::string>& aov_names() {
    static const std::vector<std::string> names = {
        "albedo",    "normal",      "depth",          "position",       "variance", "samples",
        "error",     "object_id",   "material_id",    "crypto_object", "crypto_material",
        "vector"};
    return names;
}

AovSet parse_aovs(const std::string& list) {
    AovSet set;
    size_t start = 0;
    while (start <= list.size()) {
        size_t end = list.find(',', start);
        if (end == std::string::npos) end = list.size();
        std::string name = list.substr(start, end - start);
        name.erase(0, name.find_first_not_of(' '));
        name.erase(name.find_last_not_of(' ') + 1);
        start = end + 1;
        if (name.empty()) continue;
        if (name == "all") {
            // Not the error (it changes the sample streams), nor Cryptomatte (its own
            // eight IDs per pixel and type, and three layers).
            for (size_t i = 0; i < aov_names().size(); ++i) {
                const Aov a = Aov(1u << i);
                if (a != Aov::Error && a != Aov::CryptoObject && a != Aov::CryptoMaterial)
                    set.add(a);
            }
            continue;
        }
        if (name == "cryptomatte") {
            set.add(Aov::CryptoObject);
            set.add(Aov::CryptoMaterial);
            continue;
        }
        bool found = false;
        for (size_t i = 0; i < aov_names().size(); ++i)
            if (aov_names()[i] == name) {
                set.add(Aov(1u << i));
                found = true;
            }
        if (!found) {
            std::string known;
            for (const std::string& n : aov_names()) known += (known.empty() ? "" : ", ") + n;
            throw std::invalid_argument("unknown AOV '" + name + "' (expected " + known +
                                        ", cryptomatte or all)");
        }
    }
    return set;
}

}  // namespace penumbra
