// The albedo tables that the build integrated (albedo_generator.cpp).
#include "materials/albedo/sheen_albedo_table.h"
#include "materials/albedo/specular_albedo_table.h"

#include "albedo_tables.inc"
