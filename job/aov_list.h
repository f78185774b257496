// The --aov list: names of the AOVs (core/film/aov.h) as the command line and job files
// spell them.
#pragma once

#include <string>
#include <vector>

#include "core/film/aov.h"

namespace penumbra {

// "albedo,normal,depth,position,variance,samples,error,object_id,material_id,crypto_object,
// crypto_material,vector" (any subset, any order; "cryptomatte" for both Cryptomatte layers, "all"
// for every one but error, which changes the sample streams, and Cryptomatte). Throws
// std::invalid_argument naming an unknown entry.
AovSet parse_aovs(const std::string& list);
// The names parse_aovs accepts, in Aov order.
const std::vector<std::string>& aov_names();

}  // namespace penumbra
