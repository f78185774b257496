// The grid of the specular albedo table (specular_albedo.h) and how one row of it is
// integrated: shared by the library, which reads the table the build generated, and by
// the generator that writes it (albedo_generator.cpp).
#pragma once

#include "materials/albedo/specular_albedo.h"

namespace penumbra {

struct SpecularAlbedoTable {
    static constexpr int R = SpecularAlbedoGrid::kRows;
    static constexpr int M = SpecularAlbedoGrid::kColumns;
    float ab[R][M][2];    // (A, B) per roughness row and mu column
    float average[R][2];  // 2 int (A, B) mu dmu of each row's interpolant
};

// The grid's nodes: mu = (i / (M - 1))^3, alpha = (j / (R - 1))^4.
constexpr float specular_albedo_column_mu(int i) {
    const float s = i / float(SpecularAlbedoGrid::kColumns - 1);
    return s * s * s;
}
constexpr float specular_albedo_row_alpha(int j) {
    const float t = j / float(SpecularAlbedoGrid::kRows - 1);
    return (t * t) * (t * t);
}

// The largest column i <= M - 2 with mu(i) <= mu, for mu in [0, 1] (0 for mu <= 0): the
// column at or below mu that SpecularAlbedo::at interpolates from.
int specular_albedo_column_below(float mu);

// Integrates row j of type's table (A and B at every column, and the row's average).
void integrate_specular_albedo_row(MicrofacetType type, int j, SpecularAlbedoTable& t);

// The tables the build integrated (build/materials/generated/albedo_tables.inc).
extern const SpecularAlbedoTable kSpecularAlbedoGgx;
extern const SpecularAlbedoTable kSpecularAlbedoBeckmann;

}  // namespace penumbra
