// The specular albedo tables that the build integrated (specular_albedo_generator.cpp).
#include "materials/albedo/specular_albedo_table.h"

#include "specular_albedo_table.inc"
