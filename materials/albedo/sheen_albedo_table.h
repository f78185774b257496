// The grid of the sheen albedo table (sheen_albedo.h) and how one row of it is integrated:
// shared by the library, which reads the table the build generated, and by the generator
// that writes it (albedo_generator.cpp), so that no render integrates it at start-up.
#pragma once

#include "materials/albedo/sheen_albedo.h"
#include "materials/lobes/sheen.h"

namespace penumbra {

struct SheenAlbedoTable {
    static constexpr int R = SheenAlbedoGrid::kRows;
    static constexpr int M = SheenAlbedoGrid::kColumns;
    float e[R][M];  // E per roughness row and mu column
};

// The grid's nodes: mu = (i / (M - 1))^2, r = r_min + (1 - r_min) j / (R - 1).
inline float sheen_albedo_column_mu(int i) {
    const float s = i / float(SheenAlbedoTable::M - 1);
    return s * s;
}
inline float sheen_albedo_row_roughness(int j) {
    const float r_min = CharlieSheen::kMinRoughness;
    return r_min + (1 - r_min) * (j / float(SheenAlbedoTable::R - 1));
}

// Integrates row j (64 x 64 nodes per entry).
void integrate_sheen_albedo_row(int j, SheenAlbedoTable& t);

// The table the build integrated (build/materials/generated/albedo_tables.inc).
extern const SheenAlbedoTable kSheenAlbedo;

}  // namespace penumbra
